// REPORT.md of `wavecontact reproduce`: where the seed's printed formulas depart from the
// exact solutions, and the snap-through of the wave curve beyond a = b1/2.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/minima.hpp>

#include "figure.hpp"
#include "wavecontact/stability.hpp"
#include "wavecontact/two_scale.hpp"
#include "wavecontact/waviness.hpp"

namespace wavecontact::cli {

namespace {

constexpr double pi = 3.14159265358979323846;

std::string fixed(double value, int digits) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, value);
  return buffer;
}

std::string percent(double got, double reference) {
  return fixed(100 * (got - reference) / reference, 3) + " %";
}

// The largest pressure in the zone: the best of 2001 samples, refined by Brent's method.
double maximum_pressure(const WavinessParams& p, double a, Form form) {
  auto negated = [&](double x) { return -pressure(p, a, x, form); };
  constexpr int samples = 2000;
  int best = 0;
  for (int i = 1; i < samples; ++i) {
    if (negated(a * i / samples) < negated(a * best / samples)) best = i;
  }
  const double lo = a * std::max(best - 1, 0) / samples, hi = a * std::min(best + 1, samples - 1) / samples;
  return -boost::math::tools::brent_find_minima(negated, lo, hi, 52).second;
}

// Eq. 6 applied to the printed eq. 14 by quadrature, x = a (1 - t^2).
double printed_load_by_quadrature(const WavinessParams& p, double a) {
  auto integrand = [&](double t) { return 4 * a * t * pressure(p, a, a * (1 - t * t), Form::paper); };
  return boost::math::quadrature::gauss_kronrod<double, 61>::integrate(integrand, 0.0, 1.0, 15, 1e-15);
}

std::string waviness_table() {
  std::ostringstream md;
  md << "| m | a/b1 | p(0) exact | p(0) printed | difference | max p exact | max p printed | "
        "difference | load: digits in common |\n|---|---|---|---|---|---|---|---|---|\n";
  for (double m : {0.2, 2.0, 10.0, 35.0}) {
    for (double f : {0.1, 0.25, 0.4, 0.5}) {
      const WavinessParams p{1.0, pi, m, 1.0};
      const double a = f * pi;
      const double p0 = pressure(p, a, 0.0), p0_printed = pressure(p, a, 0.0, Form::paper);
      const double top = maximum_pressure(p, a, Form::exact);
      const double top_printed = maximum_pressure(p, a, Form::paper);
      const double P = load(p, a), P_printed = printed_load_by_quadrature(p, a);
      const double digits = -std::log10(std::max(std::abs(P_printed - P) / P, 1e-17));
      md << "| " << number(m) << " | " << number(f) << " | " << fixed(p0, 6) << " | "
         << fixed(p0_printed, 6) << " | " << percent(p0_printed, p0) << " | " << fixed(top, 6)
         << " | " << fixed(top_printed, 6) << " | " << percent(top_printed, top) << " | "
         << fixed(digits, 1) << " |\n";
    }
  }
  return md.str();
}

std::string roughness_table() {
  std::ostringstream md;
  md << "| n | a/b2 | p_r(0) exact | p_r(0) eq. 20 | difference |\n|---|---|---|---|---|\n";
  for (int n : {8, 16, 32}) {
    for (double f : {0.25, 0.5, 1.0}) {
      const TwoScaleParams params{{1.0, pi, 0.0, 1.0}, {1.0, n}};
      const double a = f * pi / n;
      const double exact = TwoScaleContact(params, a, Form::exact).roughness_pressure(0);
      const double printed = TwoScaleContact(params, a, Form::paper).roughness_pressure(0);
      md << "| " << n << " | " << number(f) << " | " << fixed(exact, 8) << " | " << fixed(printed, 8)
         << " | " << percent(printed, exact) << " |\n";
    }
  }
  return md.str();
}

// The first a beyond b1/2 at which the exact pressure turns negative somewhere in the zone
// (16 probes, then bisection to b1/4096); b1 if none does.
double admissibility_limit(const WavinessParams& p) {
  double lo = p.b1 / 2, hi = p.b1;
  for (int i = 1; i < 16; ++i) {
    const double a = p.b1 / 2 * (1 + i / 16.0);
    if (!admissibility(p, a).admissible) {
      hi = a;
      break;
    }
    lo = a;
  }
  if (hi == p.b1) return hi;
  while (hi - lo > p.b1 / 4096) {
    const double mid = (lo + hi) / 2;
    (admissibility(p, mid).admissible ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

// The smallest m with a turning point of P(a), by bisection on [0.5, 1] to 1e-4.
double snap_through_onset() {
  double lo = 0.5, hi = 1.0;
  while (hi - lo > 1e-4) {
    const double mid = (lo + hi) / 2;
    (LoadCurve({1.0, pi, mid, 1.0}).unstable_ranges().empty() ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

std::string snap_through_table() {
  std::ostringstream md;
  md << "| m | unstable range of a/b1 (dP/da < 0) | peak pa/p* | pa/p* at full contact | "
        "p < 0 somewhere from a/b1 = |\n|---|---|---|---|---|\n";
  for (double m : {0.5, 1.0, 2.0, 10.0, 35.0}) {
    const WavinessParams p{1.0, pi, m, 1.0};
    const LoadCurve curve(p);
    std::string ranges;
    for (const HalfWidthRange& r : curve.unstable_ranges()) {
      ranges += (ranges.empty() ? "" : ", ") + std::string("[") + fixed(r.begin / pi, 5) + ", " +
                fixed(r.end / pi, 5) + "]";
    }
    const double limit = admissibility_limit(p) / pi;
    md << "| " << number(m) << " | " << (ranges.empty() ? "none" : ranges) << " | "
       << fixed(curve.maximum_load() / pi, 5) << " | " << fixed(curve.full_contact_load() / pi, 5)
       << " | " << (limit < 1 ? fixed(limit, 4) : "never") << " |\n";
  }
  return md.str();
}

}  // namespace

std::string discrepancy_report(const std::vector<Figure>& figures) {
  std::ostringstream md;
  md << "# wavecontact: the seed paper against the exact solutions\n\n"
        "Generated by `wavecontact reproduce`. Normalised units: b1 = pi, H1 = H2 = E* = 1 "
        "(pressures are p b1/(pi E* H), loads P/(E* H), so MATH.md's check values apply "
        "directly); pa/p* = P/(pi E* H1).\n\n"
        "## Printed eq. 14 against the exact solution of eq. 12 (waviness, a <= b1/2)\n\n"
        "Difference = (printed - exact)/exact. The load column compares the exact closed-form "
        "load with eq. 6 applied to the printed eq. 14 by 61-point Gauss-Kronrod quadrature: the "
        "two loads are equal (a symbolic identity, proven in tests/symbolic_test.cpp), so the "
        "digits in common are those of the quadrature.\n\n"
     << waviness_table()
     << "\n## Eq. 20 against the exact roughness pressure (centre of the zone, n H2 = n)\n\n"
     << roughness_table()
     << "\n## Beyond a = b1/2: snap-through and loss of contact\n\n"
        "The exact load by quadrature of MATH.md fact 7 (split at the kink x = b1/2); turning "
        "points where dP/da = 0. In the unstable range a load is carried by two zones, a "
        "stable one below the peak and an unstable one beyond it; the zone snaps to full "
        "contact when the peak load is passed. The last column is where the single-zone "
        "pressure first turns negative on the asperity's lower flank (the contact would "
        "separate there, so the single zone is not the solution).\n\n"
     << snap_through_table()
     << "\nThe two last columns meet: within the bisection's b1/4096, the pressure turns negative "
        "exactly where the load peaks, so every stable single zone is admissible and every "
        "unstable one is not.\n\nP(a) first has a turning point at m = "
     << fixed(snap_through_onset(), 4)
     << " (bisection on m to 1e-4; MATH.md states m >= 2 as the regime where it is certain).\n"
        "\n## Figures\n\n";
  for (const Figure& figure : figures) {
    md << "### " << figure.caption << "\n\n![" << figure.name << "](" << figure.name << ".png)\n\n";
  }
  return md.str();
}

}  // namespace wavecontact::cli
