// Beyond the seed: the shape-design figure (wavecontact/shape_design.hpp).
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "figure.hpp"
#include "wavecontact/shape_design.hpp"

namespace wavecontact::cli {

// max p / mean p against m for several loads, with the most uniform shape of each marked.
Figure shape_design() {
  const std::vector<double> ratios{0.05, 0.2, 0.5, 0.8};
  constexpr int samples = 60;
  constexpr double m_max = 100;
  std::ostringstream csv, optima, plot;
  csv << "kind,pa_over_pstar,m,a_over_b1,max_over_mean\n";
  for (double ratio : ratios) {
    for (int i = 0; i <= samples; ++i) {
      const double m = std::expm1(std::log1p(m_max) * i / samples);
      csv << "scan," << number(ratio) << "," << number(m) << ",";
      try {
        const PressureUniformity u = pressure_uniformity(m, ratio);
        csv << number(u.a_over_b1) << "," << number(u.max_over_mean) << "\n";
      } catch (const std::domain_error&) {  // no stable, admissible zone: a gap
        csv << "NaN,NaN\n";
      }
    }
  }
  for (double ratio : ratios) {
    const PressureUniformity best = most_uniform_shape(ratio, m_max);
    optima << (optima.tellp() > 0 ? "; " : "") << "pa/p* = " << number(ratio) << ": m = " << number(best.m)
           << " (max p/mean p = " << number(best.max_over_mean) << ")";
    csv << "optimum," << number(ratio) << "," << number(best.m) << "," << number(best.a_over_b1) << ","
        << number(best.max_over_mean) << "\n";
  }
  const int rows = samples + 1, curves = static_cast<int>(ratios.size());
  plot << "set title 'Shape design: pressure non-uniformity max p / mean p against m at fixed "
          "load (points: the optimum of wavecontact optimize-shape)'\n"
          "set xlabel 'm (shape parameter, log scale; m = 0 is off the axis)'\nset ylabel 'max p / mean p'\nset "
          "logscale x\n"
          "set xrange [0.05:100]\nset key top left\nplot ";
  for (int k = 0; k < curves; ++k) {
    const std::string color = " lc " + std::to_string(k + 1);
    plot << (k ? ", \\\n  " : "") << "'fig9.csv' skip 1" << rows_of_block(k, rows) << " using 3:5 with lines lw 2"
         << color << " title 'pa/p* = " << number(ratios[k]) << "', 'fig9.csv' skip 1 every ::" << curves * rows + k
         << "::" << curves * rows + k << " using 3:5 with points pt 7 ps 1.5" << color << " notitle";
  }
  return {"fig9",
          "Shape design (beyond the seed): max p / mean p against m at pa/p* = 0.05, 0.2, 0.5, "
          "0.8; points mark the most uniform shape (" +
              optima.str() + "). Gaps: no stable, admissible single zone.",
          csv.str(), plot.str() + "\n"};
}

}  // namespace wavecontact::cli
