// The real contact in the figures (wavecontact/contact.hpp): Fig. 6 through snap-through to
// full contact, Fig. 7 through the whole load range, and beyond the seed: the contact
// fraction and zones per period against the load (fig10), the pressure at a multi-zone
// load (fig11), the contact of a four-scale surface (fig12).
#include <cmath>
#include <future>
#include <limits>
#include <sstream>
#include <vector>

#include <boost/math/constants/constants.hpp>

#include "figure.hpp"
#include "wavecontact/contact.hpp"
#include "wavecontact/two_scale.hpp"
#include "wavecontact/waviness.hpp"

namespace wavecontact::cli {

namespace {

using boost::math::double_constants::pi;
constexpr double H1 = 1.0, b1 = 10.0, E = 1.0;  // mm, mm, pressures in units of E*
const double not_a_number = std::numeric_limits<double>::quiet_NaN();

// A curve; colour 0 is grey.
std::string lines_of(const std::string& file, const std::string& rows, const std::string& columns, int colour,
                     int width, int dash, const std::string& title) {
  return "'" + file + "' skip 1" + rows + " using " + columns + " with lines lw " + std::to_string(width) +
         (colour == 0 ? std::string(" lc rgb 'grey'") : " lc " + std::to_string(colour)) + " dt " +
         std::to_string(dash) + (title.empty() ? " notitle" : " title '" + title + "'");
}

std::string plot(const std::vector<std::string>& curves) {
  std::string s = "plot ";
  for (std::size_t k = 0; k < curves.size(); ++k) s += (k ? ", \\\n  " : "") + curves[k];
  return s + "\n";
}

// The figures' solves: known to succeed, and computed side by side on every core, so that the
// wall clock a load takes depends on the machine and its other work: they take an hour a
// load (the default budget of 60 s guards the solves of arbitrary input).
SolverOptions figure_solves() { return SolverOptions(1e-10, 0, 3600); }

// The loads of a sweep, pa/p* from small to `top`, denser at small loads.
std::vector<double> sweep_ratios(double top, int count) {
  std::vector<double> r;
  for (int i = 1; i <= count; ++i) r.push_back(top * std::pow(static_cast<double>(i) / count, 1.5));
  return r;
}

}  // namespace

TwoScaleSweeps two_scale_sweeps(const std::vector<int>& ns, double top, int count) {
  // Each sweep on its own thread: they are independent, and the slowest (n = 256) sets the time.
  std::vector<std::future<TwoScaleSweep>> pending;
  for (int n : ns) {
    for (double m : {0.0, 10.0}) {
      pending.push_back(std::async(std::launch::async, [=] {
        TwoScaleSweep s{n, m, sweep_ratios(top, count), {}};
        std::vector<double> loads;
        for (double r : s.ratios) loads.push_back(r * pi * E * H1);
        s.contacts = solve_contact(Surface(TwoScaleParams{{H1, b1, m, E}, {two_scale_H2, n}}), loads, figure_solves());
        return s;
      }));
    }
  }
  TwoScaleSweeps sweeps;
  for (std::future<TwoScaleSweep>& s : pending) sweeps.push_back(s.get());
  return sweeps;
}

// Fig. 6 to full contact: the real contact (solid), the single-zone family of the exact
// solution (thin: admissible where it meets the solid line, dashed where it interpenetrates
// or its pressure is negative) and the printed eq. 14 (dotted).
Figure contact_length() {
  const std::vector<double> ms{0, 0.2, 2, 10, 35};
  constexpr int samples = 160;
  std::ostringstream csv, script;
  csv << "m,pa_over_pstar,contact_fraction,zones,family_contact_fraction,family_pa_over_pstar,"
         "family_admissible,printed_pa_over_pstar\n";
  const std::vector<double> ratios = sweep_ratios(4.0, samples);
  for (double m : ms) {
    const WavinessParams p{H1, b1, m, E};
    std::vector<double> loads;
    for (double r : ratios) loads.push_back(r * pi * E * H1);
    const std::vector<Contact> contacts = solve_contact(Surface(p), loads, figure_solves());
    for (int i = 0; i < samples; ++i) {
      const double a = b1 * (i + 1) / samples;
      const bool printed = 1 + m * std::cos(pi * a / b1) > 0.05;
      csv << number(m) << "," << number(ratios[i]) << "," << number(contacts[i].contact_fraction()) << ","
          << contacts[i].zones_per_period() << "," << number(a / b1) << "," << number(pa_over_pstar(p, a)) << ","
          << (a < b1 && single_zone_check(Surface(p), a).solution ? 1 : 0) << ","
          << (printed ? number(pa_over_pstar(p, a, Form::paper)) : "NaN") << "\n";
    }
  }
  script << "set title \"Fig. 6: contact fraction against pa/p* to full contact, H1 = 1 mm, b1 = 10 mm\\n"
            "(thick: the contact; thin: one zone, dashed where it is not the contact; dotted: printed eq. 14)\"\n"
            "set xlabel 'pa / p*'\nset ylabel 'contact fraction (2a/L1 for one zone)'\nset key bottom right\n"
            "set xrange [0:4]\nset yrange [0:1.02]\n";
  std::vector<std::string> curves;
  for (std::size_t k = 0; k < ms.size(); ++k) {
    const std::string rows = rows_of_block(static_cast<int>(k), samples);
    const int colour = static_cast<int>(k + 1);
    curves.push_back(lines_of("fig6.csv", rows, "2:3", colour, 3, 1, "m = " + number(ms[k])));
    curves.push_back(lines_of("fig6.csv", rows, "($7 == 1 ? $6 : NaN):5", colour, 1, 1, ""));
    curves.push_back(lines_of("fig6.csv", rows, "($7 == 0 ? $6 : NaN):5", colour, 1, 2, ""));
    if (ms[k] != 0) curves.push_back(lines_of("fig6.csv", rows, "8:5", colour, 1, 3, ""));
  }
  script << plot(curves);
  return {"fig6",
          "Fig. 6: contact fraction against pa/p* to full contact: the contact (thick) leaves the single-zone "
          "family where the valley closes, then has two zones until it is full",
          csv.str(), script.str()};
}

// Fig. 7: p(0) against the load, two-scale: the contact (solid) beside the seed's single
// zone, exact (thin; dashed where it is not the contact) and printed eq. 14 + 20 (dotted),
// and the waviness alone.
Figure centre_pressure(const TwoScaleSweeps& sweeps) {
  constexpr int samples = 300;
  std::ostringstream csv;
  csv << "n,m,pa_over_pstar,p0_contact,family_pa_over_pstar,family_p0,family_admissible,printed_pa_over_pstar,"
         "printed_p0,waviness_pa_over_pstar,waviness_p0\n";
  for (const TwoScaleSweep& s : sweeps) {
    const TwoScaleParams params{{H1, b1, s.m, E}, {two_scale_H2, s.n}};
    const double pi_E_H1 = pi * E * H1;
    for (int i = 0; i < samples; ++i) {
      const double a = b1 / 2 * (i + 1) / samples;
      const TwoScaleContact exact(params, a, Form::exact), printed(params, a, Form::paper);
      const std::size_t j = static_cast<std::size_t>(i) * s.contacts.size() / samples;
      csv << s.n << "," << number(s.m) << "," << number(s.ratios[j]) << "," << number(s.contacts[j].pressure(0)) << ","
          << number(exact.load() / pi_E_H1) << "," << number(exact.waviness_pressure(0) + exact.roughness_pressure(0))
          << "," << (exact.admissible() ? 1 : 0) << "," << number(printed.load() / pi_E_H1) << ","
          << number(printed.waviness_pressure(0) + printed.roughness_pressure(0)) << ","
          << number(exact.waviness_load() / pi_E_H1) << "," << number(exact.waviness_pressure(0)) << "\n";
    }
  }
  std::string script =
      "set multiplot layout 1,2 title \"Fig. 7: p(0) against pa/p*, H1 = 1 mm, H2 = 0.15 mm, b1 = 10 mm\\n(thick: "
      "the contact; thin: one zone, dashed where not the contact; dotted: printed eq. 14 + 20; grey: waviness)\"\n"
      "set xlabel 'pa / p*'\nset ylabel 'p(0) / E*'\nset key top left font ',8'\nset xrange [0:1.2]\nset yrange "
      "[0:*]\n";
  for (int panel = 0; panel < 2; ++panel) {
    std::vector<std::string> curves;
    for (int k = 0; k < 2; ++k) {
      const int block = 2 * panel + k, colour = 2 * k + 1;
      const std::string rows = rows_of_block(block, samples), m = "m = " + number(sweeps[block].m);
      curves.push_back(lines_of("fig7.csv", rows, "3:4", colour, 3, 1, m + ", contact"));
      curves.push_back(lines_of("fig7.csv", rows, "($7 == 1 ? $5 : NaN):6", colour, 1, 1, m + ", one zone"));
      curves.push_back(lines_of("fig7.csv", rows, "($7 == 0 ? $5 : NaN):6", colour, 1, 2, ""));
      curves.push_back(lines_of("fig7.csv", rows, "8:9", colour, 1, 3, m + ", printed"));
      curves.push_back(lines_of("fig7.csv", rows, "10:11", 0, 1, 1, ""));
    }
    script += "set title 'n = " + std::to_string(sweeps[2 * panel].n) + "'\n" + plot(curves);
  }
  return {"fig7",
          "Fig. 7: p(0) against pa/p*, two-scale (H2 = 0.15 mm, n = 8 and 16, m = 0 and 10): the contact through "
          "the whole range beside the seed's single-zone solutions",
          csv.str(), script + "unset multiplot\n"};
}

// fig10: the contact fraction and the zones per period against pa/p*, the seed's two-scale
// parameters, from the shared sweeps (n = 8, 16) and sweeps to pa/p* = 2 at n = 64 and 256.
Figure contact_fraction_and_zones(const TwoScaleSweeps& shared) {
  TwoScaleSweeps sweeps = shared;
  for (TwoScaleSweep& s : two_scale_sweeps({64, 256}, 2.0, 8)) sweeps.push_back(std::move(s));
  std::ostringstream csv;
  csv << "n,m,pa_over_pstar,contact_fraction,zones,p0,max_p,error_estimate\n";
  std::vector<std::string> rows;  // each sweep's rows of the CSV, for gnuplot's `every`
  std::size_t first = 0;
  for (const TwoScaleSweep& s : sweeps) {
    for (std::size_t i = 0; i < s.contacts.size(); ++i) {
      const Contact& c = s.contacts[i];
      csv << s.n << "," << number(s.m) << "," << number(s.ratios[i]) << "," << number(c.contact_fraction()) << ","
          << c.zones_per_period() << "," << number(c.pressure(0)) << "," << number(c.max_pressure()) << ","
          << number(c.error_estimate()) << "\n";
    }
    rows.push_back(" every ::" + std::to_string(first) + "::" + std::to_string(first + s.contacts.size() - 1));
    first += s.contacts.size();
  }
  std::string script =
      "set multiplot layout 1,2 title 'fig10: the contact of the two-scale profile, H1 = 1 mm, H2 = 0.15 mm, "
      "b1 = 10 mm'\nset xlabel 'pa / p*'\nset key top left font ',8'\nset xrange [0:2]\n";
  for (int panel = 0; panel < 2; ++panel) {
    std::vector<std::string> curves;
    for (std::size_t k = 0; k < sweeps.size(); ++k) {
      const std::string title = "n = " + std::to_string(sweeps[k].n) + ", m = " + number(sweeps[k].m);
      curves.push_back(lines_of("fig10.csv", rows[k], panel == 0 ? "3:4" : "3:5", static_cast<int>(k + 1), 2,
                                sweeps[k].m == 0 ? 1 : 2, title));
    }
    script += panel == 0 ? "set title 'contact fraction'\nset ylabel 'contact length / period'\n"
                         : "set title 'zones per period'\nset ylabel 'zones'\nset logscale y\n";
    script += plot(curves);
  }
  return {"fig10", "fig10: contact fraction and zones per period against pa/p*, the seed's two-scale parameters",
          csv.str(), script + "unset multiplot\n"};
}

// fig11: the pressure and the gap at a multi-zone load (n = 8, m = 0, pa/p* = 0.3), with the
// seed's single zone (eq. 21, exact parts) carrying the same load.
Figure multi_zone_pressure() {
  constexpr double ratio = 0.3;
  constexpr int n = 8, samples = 2001;
  const TwoScaleParams params{{H1, b1, 0, E}, {two_scale_H2, n}};
  const double P = ratio * pi * E * H1;
  const Contact c = solve_contact(Surface(params), P, figure_solves());
  const std::vector<Equilibrium> family = two_scale_half_widths(params, P);
  const double a = family.empty() ? not_a_number : family.front().a;
  const TwoScaleContact single(params, std::isfinite(a) ? a : b1 / 4);
  std::ostringstream csv;
  csv << "x_mm,p_contact,gap_mm,p_single_zone\n";
  for (int i = 0; i < samples; ++i) {
    const double x = -b1 + 2 * b1 * i / (samples - 1.0);
    const double p1 =
        std::isfinite(a) && std::fabs(x) < a ? single.waviness_pressure(x) + single.roughness_pressure(x) : 0;
    csv << number(x) << "," << number(c.pressure(x)) << "," << number(c.gap(x)) << "," << number(p1) << "\n";
  }
  const std::string title =
      "fig11: n = 8, m = 0, H2 = 0.15 mm, pa/p* = 0.3: " + std::to_string(c.zones_per_period()) + " zones per period";
  std::string script = "set multiplot layout 2,1 title '" + title +
                       "'\nset xlabel 'x [mm]'\nset key top right\n"
                       "set ylabel 'p / E*'\n" +
                       plot({lines_of("fig11.csv", "", "1:2", 1, 2, 1, "the contact"),
                             lines_of("fig11.csv", "", "1:4", 2, 1, 2,
                                      "one zone carrying the load (eq. 21, exact parts): not the contact")}) +
                       "set ylabel 'gap [mm]'\n" +
                       plot({lines_of("fig11.csv", "", "1:3", 3, 2, 1, "gap of the contact")}) + "unset multiplot\n";
  return {"fig11",
          "fig11: pressure and gap at a multi-zone load (n = 8, m = 0, pa/p* = 0.3) beside the seed's single zone "
          "carrying the same load",
          csv.str(), script};
}

// fig12: the contact of a four-scale surface (the wave curve at m = 0 and roughness of
// heights 0.1, 0.05, 0.025, 0.0125 mm at n = 4, 16, 64, 256), over the period and over one
// period of the finest scale around its most loaded asperity.
Figure four_scale_contact() {
  const std::vector<Harmonic> scales{{0.1, 4}, {0.05, 16}, {0.025, 64}, {0.0125, 256}};
  constexpr double P = 2.0;  // per period, in E* mm (pa/p* = 2/pi)
  const Contact c = solve_contact(Surface(WavinessParams{H1, b1, 0, E}, scales), P, figure_solves());
  const double finest = 2 * b1 / scales.back().n;
  // The zoom: the most loaded zone narrower than the finest wavelength (an asperity of it),
  // centred on the crest of the finest scale nearest to its highest pressure.
  const ContactZone* asperity = nullptr;
  for (const ContactZone& z : c.zones()) {
    if (z.x_end - z.x_start < finest && (!asperity || z.max_pressure > asperity->max_pressure)) asperity = &z;
  }
  const double zoom_centre = std::round((asperity ? asperity->x_of_max_pressure : 0.0) / finest) * finest;
  std::ostringstream csv;
  csv << "panel,x_mm,p,gap_mm,in_contact\n";
  const auto rows = [&](int panel, double from, double to, int samples) {
    for (int i = 0; i < samples; ++i) {
      const double x = from + (to - from) * i / (samples - 1.0);
      const double p = c.pressure(x);
      csv << panel << "," << number(x) << "," << number(p) << "," << number(c.gap(x)) << "," << (p > 0 ? 1 : 0) << "\n";
    }
  };
  rows(0, -b1, b1, 16001);
  rows(1, zoom_centre - finest / 2, zoom_centre + finest / 2, 2001);
  const std::string pmax = number(1.08 * c.max_pressure());
  const std::string title =
      "fig12: four scales (H = 0.1, 0.05, 0.025, 0.0125 mm at n = 4, 16, 64, 256), m = 0, P = " + number(P) +
      " E* mm: " + std::to_string(c.zones_per_period()) + " zones per period";
  const auto bar = [&](int panel) {  // the zones as a bar below the axis
    return "($1 == " + std::to_string(panel) + " && $5 == 1 ? -0.04 * " + pmax + " : NaN)";
  };
  std::string script = "set multiplot layout 2,1 title '" + title + "'\nset key top right font ',8'\n";
  script += "set xlabel 'x [mm]'\nset ylabel 'p / E*'\nset yrange [-0.08 * " + pmax + ":" + pmax + "]\n" +
            plot({lines_of("fig12.csv", "", "($1 == 0 ? $2 : NaN):3", 1, 1, 1, "pressure over the period"),
                  lines_of("fig12.csv", "", "($1 == 0 ? $2 : NaN):" + bar(0), 0, 4, 1, "the zones")});
  script +=
      "set xlabel 'x [mm], one period of the finest scale (n = 256) around its most loaded asperity'\n"
      "set y2label 'gap [mm]'\nset ytics nomirror\nset y2tics\nset autoscale y2\n" +
      plot({lines_of("fig12.csv", "", "($1 == 1 ? $2 : NaN):3", 1, 2, 1, "pressure"),
            lines_of("fig12.csv", "", "($1 == 1 ? $2 : NaN):" + bar(1), 0, 4, 1, "the zones"),
            lines_of("fig12.csv", "", "($1 == 1 ? $2 : NaN):4 axes x1y2", 3, 2, 2, "gap (right axis)")}) +
      "unset multiplot\n";
  return {"fig12",
          "fig12: the contact of a four-scale surface at P = 2 E* mm: the pressure over the period with its zones, and "
          "one period of the finest scale (pressure and gap) around its most loaded asperity",
          csv.str(), script};
}

}  // namespace wavecontact::cli
