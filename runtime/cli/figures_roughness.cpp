// Figs. 2, 4 and 8 of the seed paper: the two-scale profile (Fig. 7: figures_contact.cpp).
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include <boost/math/constants/constants.hpp>

#include "figure.hpp"
#include "wavecontact/two_scale.hpp"
#include "wavecontact/waviness.hpp"

namespace wavecontact::cli {

namespace {

using boost::math::double_constants::pi;
constexpr double H1 = 1.0, b1 = 10.0, E = 1.0;  // mm, mm, pressures in units of E*
const double not_a_number = std::numeric_limits<double>::quiet_NaN();

// Solid for the exact solution, dashed for the printed formulas, one colour per curve.
std::string curve(const std::string& file, const std::string& rows, const std::string& columns, int colour, bool exact,
                  const std::string& title) {
  return "'" + file + "' skip 1" + rows + " using " + columns + " with lines lw " + (exact ? "2" : "1") + " lc " +
         std::to_string(colour) + " dt " + (exact ? "1" : "2") + " title '" + title + "'";
}

std::string plot(const std::vector<std::string>& curves) {
  std::string s = "plot ";
  for (std::size_t k = 0; k < curves.size(); ++k) s += (k ? ", \\\n  " : "") + curves[k];
  return s + "\n";
}

}  // namespace

// Fig. 2: the two-scale profile y = w + r (eq. 1), H2 = 0.05 mm, n = 16.
Figure two_scale_profiles() {
  constexpr double H2 = 0.05;
  constexpr int n = 16, samples = 2001;
  std::ostringstream csv;
  csv << "x_mm,y_m0_mm,y_m10_mm\n";
  for (int i = 0; i < samples; ++i) {
    const double x = -b1 + 2 * b1 * i / (samples - 1.0), r = H2 * std::cos(n * pi * x / b1);
    csv << number(x) << "," << number(wave_curve({H1, b1, 0, E}, x) + r) << ","
        << number(wave_curve({H1, b1, 10, E}, x) + r) << "\n";
  }
  return {"fig2", "Fig. 2: two-scale profile, H2 = 0.05 mm, n = 16, m = 0 and 10", csv.str(),
          "set title 'Fig. 2: two-scale profile, H1 = 1 mm, b1 = 10 mm, H2 = 0.05 mm, n = 16'\n"
          "set xlabel 'x [mm]'\nset ylabel 'y [mm]'\nset key outside right\n" +
              plot({curve("fig2.csv", "", "1:2", 1, true, "m = 0"), curve("fig2.csv", "", "1:3", 2, true, "m = 10")})};
}

// Fig. 4: the bracket of eq. 17, s(v) = sin(n x^)/n with v = tan(x^/2), for v in [0, 1].
Figure roughness_integrand() {
  const std::vector<int> ns{8, 16, 32};
  constexpr int samples = 1001;
  std::ostringstream csv;
  csv << "v,s_n8,s_n16,s_n32\n";
  for (int i = 0; i < samples; ++i) {
    const double v = i / (samples - 1.0);
    csv << number(v);
    for (int n : ns) csv << "," << number(std::sin(2 * n * std::atan(v)) / n);
    csv << "\n";
  }
  std::vector<std::string> curves;
  for (std::size_t k = 0; k < ns.size(); ++k) {
    curves.push_back(curve("fig4.csv", "", "1:" + std::to_string(k + 2), static_cast<int>(k + 1), true,
                           "n = " + std::to_string(ns[k])));
  }
  return {"fig4", "Fig. 4: s(v), the integrand of eq. 17, for n = 8, 16, 32", csv.str(),
          "set title 'Fig. 4: s(v) = sin(n x)/n, v = tan(x/2) (eq. 17)'\n"
          "set xlabel 'v'\nset ylabel 's(v)'\nset key outside right\n" +
              plot(curves)};
}

namespace {

// One two-scale case of Figs. 7 and 8: H2 = 0.15 mm, the given n and m.
struct Case {
  int n;
  double m;
};
const std::vector<Case> cases{{8, 0}, {8, 10}, {16, 0}, {16, 10}};

// One panel per n (cases 0-1: n = 8, cases 2-3: n = 16); curves(rows, colour, "m = ...")
// gives the curves of one case, whose rows are its block of `samples` lines.
template <typename Curves>
std::string panels_by_n(int samples, Curves&& curves) {
  std::string script;
  for (int panel = 0; panel < 2; ++panel) {
    std::vector<std::string> all;
    for (int k = 0; k < 2; ++k) {
      const int block = 2 * panel + k;
      for (auto& c : curves(rows_of_block(block, samples), 2 * k + 1, "m = " + number(cases[block].m))) {
        all.push_back(std::move(c));
      }
    }
    script += "set title 'n = " + std::to_string(cases[2 * panel].n) + "'\n" + plot(all);
  }
  return script + "unset multiplot\n";
}

}  // namespace

// Fig. 8: contact area 2a/L1 against pa/p* on a <= b2, two-scale and single-scale.
Figure two_scale_contact_area() {
  constexpr int samples = 200;
  std::ostringstream csv;
  csv << "n,m,contact_fraction,pa_over_pstar_two_scale_exact,pa_over_pstar_two_scale_printed,"
         "pa_over_pstar_single,admissible\n";
  for (const Case& c : cases) {
    const TwoScaleParams params{{H1, b1, c.m, E}, {two_scale_H2, c.n}};
    const double b2 = b1 / c.n, pi_E_H1 = pi * E * H1;
    for (int i = 1; i <= samples; ++i) {
      const double a = b2 * i / samples;
      const TwoScaleContact exact(params, a, Form::exact), printed(params, a, Form::paper);
      csv << c.n << "," << number(c.m) << "," << number(a / b1) << ","
          << number(exact.admissible() ? exact.load() / pi_E_H1 : not_a_number) << ","
          << number(printed.load() / pi_E_H1) << "," << number(exact.waviness_load() / pi_E_H1) << ","
          << (exact.admissible() ? 1 : 0) << "\n";
    }
  }
  std::string script =
      "set multiplot layout 1,2 title 'Fig. 8: contact area against mean pressure, a <= b2 "
      "(solid: exact; dashed: printed eq. 14/20; gaps: no admissible single zone)'\n"
      "set xlabel 'pa / p*'\nset ylabel '2a / L1'\nset key bottom right font ',8'\n";
  script += panels_by_n(samples, [](const std::string& rows, int colour, const std::string& m) {
    return std::vector<std::string>{curve("fig8.csv", rows, "4:3", colour, true, m + ", two-scale, exact"),
                                    curve("fig8.csv", rows, "5:3", colour, false, m + ", two-scale, printed"),
                                    curve("fig8.csv", rows, "6:3", colour + 1, true, m + ", single-scale")};
  });
  return {"fig8",
          "Fig. 8: contact area against mean pressure, two-scale against single-scale, n = 8 and 16, m = 0 and 10",
          csv.str(), script};
}

}  // namespace wavecontact::cli
