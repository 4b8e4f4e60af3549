// Figs. 1, 5a and 5b of the seed paper: the waviness alone (Fig. 6: figures_contact.cpp).
#include <cmath>
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
    plot << (k ? ", " : "") << "'fig1.csv' skip 1 using 1:" << k + 2 << " with lines lw 2 title 'm = " << number(ms[k])
         << "'";
  }
  return {"fig1", "Fig. 1: the parametric wave curve, m = 0.2, 2, 8, 35, 250", csv.str(), plot.str() + "\n"};
}

// Fig. 5: pressure distributions for several m, one panel per contact half-width, exact
// (solid) against the printed eq. 14 (dashed; beyond b1/2 only where its continuation is
// defined, 1 + m cos(pi a/b1) > 0).
Figure pressure_distributions(const std::string& name, const std::string& caption, const std::string& title,
                              const std::vector<double>& fractions, double clip) {
  const std::vector<double> ms{0, 0.2, 2, 10, 35};
  constexpr int samples = 201;
  std::ostringstream csv, plot;
  csv << "a_over_b1,m,x_mm,p_exact_over_E,p_paper_over_E\n";
  plot << "set multiplot layout 1," << fractions.size() << " title '" << title
       << " H1 = 1 mm, b1 = 10 mm (solid: exact; dashed: printed eq. 14)'\n"
          "set xlabel 'x [mm]'\nset ylabel 'p / E*'\nset key top center font ',8'\n";
  int block = 0;
  for (double f : fractions) {
    std::vector<std::string> curves;
    for (std::size_t k = 0; k < ms.size(); ++k, ++block) {
      const WavinessParams p{H1, b1, ms[k], E};
      const double a = f * b1;
      const bool printed = f <= 0.5 || 1 + ms[k] * std::cos(M_PI * f) > 0;
      for (int i = 0; i < samples; ++i) {
        const double x = -a + 2 * a * i / (samples - 1.0);
        csv << number(f) << "," << number(ms[k]) << "," << number(x) << "," << number(pressure(p, a, x, Form::exact))
            << "," << (printed ? number(pressure(p, a, x, Form::paper)) : "NaN") << "\n";
      }
      const std::string rows = rows_of_block(block, samples);
      const std::string color = " lc " + std::to_string(k + 1);
      curves.push_back("'" + name + ".csv' skip 1" + rows + " using 3:4 with lines lw 2" + color +
                       " dt 1 title 'm = " + number(ms[k]) + " exact'");
      if (ms[k] != 0 && printed) {  // identical at m = 0 (Westergaard)
        curves.push_back("'" + name + ".csv' skip 1" + rows + " using 3:5 with lines lw 1" + color +
                         " dt 2 title 'm = " + number(ms[k]) + " printed'");
      }
    }
    // The printed eq. 14 has tall edge peaks for large m: clip them.
    plot << "set title 'a = " << number(f) << " b1'\nset yrange [" << (f > 0.5 ? "*" : "0") << ":"
         << (f < 0.4 ? "*" : number(clip)) << "]\nplot ";
    for (std::size_t k = 0; k < curves.size(); ++k) plot << (k ? ", \\\n  " : "") << curves[k];
    plot << (f > 0.5 ? ", 0 with lines lc 'black' dt 3 notitle" : "") << "\n";
  }
  plot << "unset multiplot\n";
  return {name, caption, csv.str(), plot.str()};
}

Figure single_asperity_pressure() {
  return pressure_distributions("fig5a",
                                "Fig. 5a: pressure, single-asperity regime (a = 0.25 b1 and 0.5 b1), exact and printed",
                                "Fig. 5a: single-asperity regime,", {0.25, 0.5}, 3.5);
}

Figure periodic_pressure() {
  return pressure_distributions(
      "fig5b",
      "Fig. 5b: pressure, periodic regime (a = 0.75 b1 and 0.95 b1); negative where the single "
      "zone is not admissible",
      "Fig. 5b: periodic regime (p < 0: no single zone; the contact separates),", {0.75, 0.95}, 3.5);
}

}  // namespace wavecontact::cli
