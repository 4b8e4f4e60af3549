#include "cauchy_atom_table.hpp"

#include <cmath>

#include <boost/math/constants/constants.hpp>

namespace wavecontact::detail {

CauchyAtomTable::CauchyAtomTable(const Atoms& atoms, int count, const std::vector<double>& etas) : count_(count) {
  constexpr double pi = boost::math::double_constants::pi;
  std::map<long, std::size_t> points;
  for (double eta : etas) {
    if (std::isfinite(eta)) ++points[static_cast<long>(std::floor(eta))];
  }
  std::vector<double> values(static_cast<std::size_t>(nodes * count));
  for (const auto& [k, n] : points) {
    if (n < static_cast<std::size_t>(nodes)) continue;
    // Chebyshev nodes of the first kind, xi_i = cos(theta_i), eta = k + (1 + xi)/2.
    for (int i = 0; i < nodes; ++i) {
      const double eta = static_cast<double>(k) + (1 + std::cos(pi * (i + 0.5) / nodes)) / 2;
      atoms(std::expm1(eta), std::exp(eta), &values[static_cast<std::size_t>(i * count)]);
    }
    std::vector<double>& c = panels_[k];
    c.assign(static_cast<std::size_t>(nodes * count), 0.0);
    for (int a = 0; a < count; ++a) {
      for (int j = 0; j < nodes; ++j) {
        double sum = 0;
        for (int i = 0; i < nodes; ++i) sum += values[static_cast<std::size_t>(i * count + a)] * std::cos(pi * j * (i + 0.5) / nodes);
        c[static_cast<std::size_t>(a * nodes + j)] = (j == 0 ? 1.0 : 2.0) * sum / nodes;
      }
    }
  }
}

bool CauchyAtomTable::evaluate(double eta, double* out) const {
  if (panels_.empty() || !std::isfinite(eta)) return false;
  const long k = static_cast<long>(std::floor(eta));
  const auto panel = panels_.find(k);
  if (panel == panels_.end()) return false;
  const double xi = 2 * (eta - static_cast<double>(k)) - 1, twice = 2 * xi;
  for (int a = 0; a < count_; ++a) {  // Clenshaw's recurrence
    const double* c = &panel->second[static_cast<std::size_t>(a * nodes)];
    double b1 = 0, b2 = 0;
    for (int j = nodes - 1; j >= 1; --j) {
      const double b = twice * b1 + (c[j] - b2);
      b2 = b1;
      b1 = b;
    }
    out[a] = xi * b1 + (c[0] - b2);
  }
  return true;
}

}  // namespace wavecontact::detail
