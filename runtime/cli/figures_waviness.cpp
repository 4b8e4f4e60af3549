// Figs. 1, 5a and 6 of the seed paper: the waviness alone.
#include <cstdio>
#include <sstream>
#include <vector>

#include "figure.hpp"
#include "wavecontact/waviness.hpp"

namespace wavecontact::cli {

namespace {

// The seed's Figs. 1, 5, 6: H1 = 1 mm, b1 = 10 mm; pressures in units of E*.
constexpr double H1 = 1.0, b1 = 10.0, E = 1.0;

}  // namespace

std::string number(double value) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.10g", value);
  return buffer;
}

std::string rows_of_block(int block, int rows) {
  return " every ::" + std::to_string(block * rows) + "::" + std::to_string((block + 1) * rows - 1);
}

// Fig. 1: the parametric wave curve for several m.
Figure wave_curves() {
  const std::vector<double> ms{0.2, 2, 8, 35, 250};
  std::ostringstream csv, plot;
  csv << "x_mm";
  for (double m : ms) csv << ",w_m" << number(m) << "_mm";
  csv << "\n";
  for (int i = 0; i <= 400; ++i) {
    const double x = -b1 + 2 * b1 * i / 400.0;
    csv << number(x);
    for (double m : ms) csv << "," << number(wave_curve({H1, b1, m, E}, x));
    csv << "\n";
  }
  plot << "set title 'Fig. 1: parametric wave curve w(x, m), H1 = 1 mm, b1 = 10 mm'\n"
          "set xlabel 'x [mm]'\nset ylabel 'w [mm]'\nset key outside right\nplot ";
  for (std::size_t k = 0; k < ms.size(); ++k) {
    plot << (k ? ", " : "") << "'fig1.csv' skip 1 using 1:" << k + 2 << " with lines lw 2 title 'm = "
         << number(ms[k]) << "'";
  }
  return {"fig1", csv.str(), plot.str() + "\n"};
}

// Fig. 5a: pressure distributions, single-asperity regime (a <= b1/2), exact (solid)
// against the printed eq. 14 (dashed).
Figure pressure_distributions() {
  const std::vector<double> ms{0, 0.2, 2, 10, 35};
  const std::vector<double> fractions{0.25, 0.5};
  constexpr int samples = 201;
  std::ostringstream csv, plot;
  csv << "a_over_b1,m,x_mm,p_exact_over_E,p_paper_over_E\n";
  plot << "set multiplot layout 1,2 title 'Fig. 5a: pressure for H1 = 1 mm, b1 = 10 mm "
          "(solid: exact; dashed: printed eq. 14)'\n"
          "set xlabel 'x [mm]'\nset ylabel 'p / E*'\nset key top center font ',8'\n";
  int block = 0;
  for (double f : fractions) {
    std::vector<std::string> curves;
    for (std::size_t k = 0; k < ms.size(); ++k, ++block) {
      const WavinessParams p{H1, b1, ms[k], E};
      const double a = f * b1;
      for (int i = 0; i < samples; ++i) {
        const double x = -a + 2 * a * i / (samples - 1.0);
        csv << number(f) << "," << number(ms[k]) << "," << number(x) << ","
            << number(pressure(p, a, x, Form::exact)) << ","
            << number(pressure(p, a, x, Form::paper)) << "\n";
      }
      const std::string rows = rows_of_block(block, samples);
      const std::string color = " lc " + std::to_string(k + 1);
      curves.push_back("'fig5.csv' skip 1" + rows + " using 3:4 with lines lw 2" + color +
                       " dt 1 title 'm = " + number(ms[k]) + " exact'");
      if (ms[k] != 0) {  // identical at m = 0 (Westergaard)
        curves.push_back("'fig5.csv' skip 1" + rows + " using 3:5 with lines lw 1" + color +
                         " dt 2 title 'm = " + number(ms[k]) + " printed'");
      }
    }
    // The printed eq. 14 has tall edge peaks for large m; clip them at a = b1/2.
    plot << "set title 'a = " << number(f) << " b1'\nset yrange [0:" << (f < 0.4 ? "*" : "3.5")
         << "]\nplot ";
    for (std::size_t k = 0; k < curves.size(); ++k) plot << (k ? ", \\\n  " : "") << curves[k];
    plot << "\n";
  }
  plot << "unset multiplot\n";
  return {"fig5", csv.str(), plot.str()};
}

// Fig. 6: contact length against mean pressure (a <= b1/2). The printed eq. 14
// integrates to the same load, so one curve per m.
Figure contact_length() {
  const std::vector<double> ms{0, 0.2, 2, 10, 35};
  std::ostringstream csv, plot;
  csv << "m,pa_over_pstar,contact_fraction\n";
  for (double m : ms) {
    const WavinessParams p{H1, b1, m, E};
    for (int i = 1; i <= 200; ++i) {
      const double a = b1 / 2 * i / 200.0;
      csv << number(m) << "," << number(pa_over_pstar(p, a)) << ","
          << number(contact_fraction(p, a)) << "\n";
    }
  }
  plot << "set title 'Fig. 6: 2a/L1 against pa/p* (exact; printed eq. 14 gives the same load)'\n"
          "set xlabel 'pa / p*'\nset ylabel '2a / L1'\nset key bottom right\nplot ";
  for (std::size_t k = 0; k < ms.size(); ++k) {
    plot << (k ? ", " : "") << "'fig6.csv' skip 1" << rows_of_block(static_cast<int>(k), 200)
         << " using 2:3 with lines lw 2 title 'm = " << number(ms[k]) << "'";
  }
  return {"fig6", csv.str(), plot.str() + "\n"};
}

}  // namespace wavecontact::cli
