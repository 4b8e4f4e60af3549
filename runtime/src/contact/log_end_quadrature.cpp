#include "log_end_quadrature.hpp"

#include <cmath>

#include <boost/math/quadrature/gauss.hpp>

namespace wavecontact::detail {

const std::vector<LogEndNode>& log_end_nodes() {
  static const std::vector<LogEndNode> nodes = [] {
    constexpr int power = 5, panels = 6;
    using rule = boost::math::quadrature::gauss<double, 30>;  // 15 pairs of abscissae +-x_i
    std::vector<LogEndNode> table;
    const auto add = [&](double w, double weight) {
      const double u = std::pow(w, power), v = std::pow(1 - w, power), d = u + v;
      table.push_back({u / d, v / d, weight * power * std::pow(w * (1 - w), power - 1) / (d * d)});
    };
    for (int panel = 0; panel < panels; ++panel) {
      const double middle = (panel + 0.5) / panels, half = 0.5 / panels;
      for (std::size_t i = 0; i < rule::abscissa().size(); ++i) {
        add(middle - half * rule::abscissa()[i], half * rule::weights()[i]);
        add(middle + half * rule::abscissa()[i], half * rule::weights()[i]);
      }
    }
    return table;
  }();
  return nodes;
}

}  // namespace wavecontact::detail
