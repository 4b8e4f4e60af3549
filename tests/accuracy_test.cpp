// Accuracy of the generated evaluators, through the runtime API, against CLN
// high-precision evaluation (40 digits) of the same derived expressions in v-form,
// measured in units of double epsilon (Boost.Math style: max, mean, worst input).
#define BOOST_TEST_MODULE accuracy
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <array>
#include <functional>
#include <iomanip>
#include <random>
#include <sstream>
#include <vector>

#include "emit/file_contents.hpp"
#include <boost/math/special_functions/cos_pi.hpp>

#include "formulas/user_profile.hpp"
#include "formulas/wave_curve.hpp"
#include "high_precision.hpp"
#include "isa_under_test.hpp"
#include "wavecontact/profile.hpp"
#include "wavecontact/stability.hpp"
#include "wavecontact/two_scale.hpp"
#include "wavecontact/waviness.hpp"
#include "wavecontact/waviness_zone.hpp"

using wavecontact::test::error_in_eps;
using wavecontact::test::evaluate;
using wavecontact::test::PhysicalPoint;

namespace {

constexpr double tolerance_eps = 64;

const wavecontact::derive::WavinessDerivation& waviness() {
  static const auto d = wavecontact::derive::derive_waviness();
  return d;
}

// The domain of the issue: m from 0 to 1e4, a up to b1/2 inclusive, x from 0 to within
// 1e-9 of a; several b1, E, H1 so that the physical scaling is exercised too.
std::vector<PhysicalPoint> domain_points() {
  const std::vector<double> ms{0, 1e-3, 0.2, 0.5, 1, 2, 10, 100, 1e3, 1e4};
  const std::vector<double> a_fractions{1e-4, 0.01, 0.1, 0.25, 0.4, 0.49, 0.4999999, 0.5};
  const std::vector<double> x_fractions{0,     1e-3,     0.1,      0.3,      0.5,  0.7, 0.9, 0.99,
                                        0.999, 1 - 1e-6, 1 - 1e-9, 1 - 3e-9, 0.25, 0.6, 0.95};
  const std::vector<std::array<double, 3>> scales{{1, 1, 1}, {2.5e9, 1e-3, 10}, {7, 0.3, 3.7}};
  std::vector<PhysicalPoint> points;
  std::size_t k = 0;
  for (double m : ms) {
    for (double fa : a_fractions) {
      for (double fx : x_fractions) {
        const auto& [E, H1, b1] = scales[k++ % scales.size()];
        const double a = fa * b1;
        points.push_back({E, H1, b1, m, a, fx * a});
      }
    }
  }
  return points;
}

struct ErrorReport {
  std::string name;
  double max = 0, sum = 0;
  std::size_t count = 0;
  PhysicalPoint worst{};

  void add(double eps, const PhysicalPoint& p) {
    sum += eps;
    ++count;
    if (eps > max) max = eps, worst = p;
  }
  std::string summary() const {
    std::ostringstream os;
    os << std::setprecision(4) << name << ": " << count << " points, max " << max << " eps, mean " << sum / count
       << " eps, worst at m = " << worst.m << ", a/b1 = " << worst.a / worst.b1 << ", x/a = " << worst.x / worst.a
       << ", b1 = " << worst.b1;
    return os.str();
  }
};

void check(const ErrorReport& report) {
  BOOST_TEST_MESSAGE(report.summary());
  BOOST_TEST(report.max <= tolerance_eps, report.summary());
}

}  // namespace

BOOST_AUTO_TEST_CASE(pressure_within_64_eps) {
  wavecontact::test::Precision precision(wavecontact::test::reference_digits);
  const auto& d = waviness();
  ErrorReport exact{"pressure, exact"}, paper{"pressure, printed eq. 14"};
  // The array API takes its own path (the vectorised kernel where the CPU has AVX2 + FMA):
  // each point sits in a 5-point array with points of the next period, so that both the
  // 4-wide body and the padded tail of the kernel are measured.
  ErrorReport array_exact{"pressure, exact, array API"}, array_paper{"pressure, printed, array API"};
  for (const auto& p : domain_points()) {
    const wavecontact::WavinessParams params{p.H1, p.b1, p.m, p.E};
    const auto v = p.v_variables();
    const auto reference = evaluate(d.pressure_v.at(0), v);
    const auto paper_reference = evaluate(d.paper_pressure_v.at(0), v);
    exact.add(error_in_eps(wavecontact::pressure(params, p.a, p.x, wavecontact::Form::exact), reference), p);
    paper.add(error_in_eps(wavecontact::pressure(params, p.a, p.x, wavecontact::Form::paper), paper_reference), p);
    Eigen::ArrayXd xs(5);
    xs << 2 * p.b1, p.x, -p.x, 4 * p.b1, p.x;
    const Eigen::ArrayXd got = wavecontact::pressure(params, p.a, xs, wavecontact::Form::exact);
    const Eigen::ArrayXd got_paper = wavecontact::pressure(params, p.a, xs, wavecontact::Form::paper);
    for (int i : {1, 2, 4}) {
      array_exact.add(error_in_eps(got[i], reference), p);
      array_paper.add(error_in_eps(got_paper[i], paper_reference), p);
    }
  }
  BOOST_TEST(exact.count >= 1000u);
  check(exact);
  check(paper);
  check(array_exact);
  check(array_paper);
}

BOOST_AUTO_TEST_CASE(load_within_64_eps) {
  wavecontact::test::Precision precision(wavecontact::test::reference_digits);
  const auto& d = waviness();
  ErrorReport load{"load"}, ratio{"pa/p*"};
  for (const auto& p : domain_points()) {
    if (p.x != 0) continue;  // one point per (m, a)
    const wavecontact::WavinessParams params{p.H1, p.b1, p.m, p.E};
    const auto v = p.v_variables();
    load.add(error_in_eps(wavecontact::load(params, p.a), evaluate(d.load_v.at(0), v)), p);
    ratio.add(error_in_eps(wavecontact::pa_over_pstar(params, p.a), evaluate(d.pa_over_pstar_v.at(0), v)), p);
  }
  check(load);
  check(ratio);
}

namespace {

// A closed form of sub-interval moment terms (c sqrt(r) I_{j,l}(z) in angle atoms) at 40
// digits, the atoms from the exact a and b1: Ca = cos(pi a/b1), Sa = 1 - Ca.
GiNaC::numeric evaluate_moments(const std::vector<wavecontact::derive::MomentTerm>& terms, const PhysicalPoint& p) {
  using wavecontact::test::exact;
  namespace sym = wavecontact::derive::sym;
  const GiNaC::numeric Ca = GiNaC::cos(GiNaC::ex_to<GiNaC::numeric>((GiNaC::Pi * exact(p.a) / exact(p.b1)).evalf()));
  GiNaC::exmap point{
      {sym::Ca(), Ca}, {sym::Sa(), 1 - Ca}, {sym::E(), exact(p.E)}, {sym::H1(), exact(p.H1)}, {sym::m(), exact(p.m)}};
  return GiNaC::ex_to<GiNaC::numeric>(wavecontact::derive::as_ex(terms).subs(point).evalf());
}

}  // namespace

// Beyond b1/2 (the zone reaches the |cos| branch of eq. 2): the load, pa/p* and dP/da in
// closed form (derive/engine/sub_interval.hpp, I_{j,l} in wavecontact/detail/quadratic_moment.hpp) against
// the same derived forms at 40 digits, over m from 0 to 1e4 and a from just above b1/2 to b1:
// the load, pa/p* and dP/da within 64 eps (dP/da from the moments of (1 + v^2) g' + v g, so
// that nothing cancels as the flank piece shrinks, a -> b1/2+).
BOOST_AUTO_TEST_CASE(load_beyond_half_within_64_eps) {
  wavecontact::test::Precision precision(wavecontact::test::reference_digits);
  const auto& d = waviness();
  ErrorReport load{"load, a > b1/2"}, ratio{"pa/p*, a > b1/2"}, slope{"dP/da, a > b1/2"};
  const std::vector<std::array<double, 3>> scales{{1, 1, 1}, {2.5e9, 1e-3, 10}, {7, 0.3, 3.7}};
  std::size_t k = 0;
  for (double m : {0.0, 1e-3, 0.2, 0.5, 0.99, 1.0, 1.01, 2.0, 10.0, 100.0, 1e3, 1e4}) {
    for (double fa : {0.5000001, 0.501, 0.55, 0.6, 0.75, 0.9, 0.99, 0.9999, 1.0}) {
      const auto& [E, H1, b1] = scales[k++ % scales.size()];
      const PhysicalPoint p{E, H1, b1, m, fa * b1, 0};
      const wavecontact::WavinessParams params{H1, b1, m, E};
      const GiNaC::numeric P = evaluate_moments(d.beyond_half.load_angle, p);
      load.add(error_in_eps(wavecontact::load(params, p.a), P), p);
      ratio.add(error_in_eps(wavecontact::pa_over_pstar(params, p.a),
                             P / GiNaC::ex_to<GiNaC::numeric>((GiNaC::Pi * p.E * p.H1).evalf())),
                p);
      if (fa < 1) {  // dP/da = (pi/b1) sin(pi a/b1) F vanishes at a = b1
        const GiNaC::numeric F = evaluate_moments(d.beyond_half.load_slope_factor, p);
        const GiNaC::numeric angle = GiNaC::ex_to<GiNaC::numeric>(
            (GiNaC::Pi * wavecontact::test::exact(p.a) / wavecontact::test::exact(b1)).evalf());
        const GiNaC::numeric dPda =
            GiNaC::ex_to<GiNaC::numeric>((GiNaC::Pi / wavecontact::test::exact(b1)).evalf()) * GiNaC::sin(angle) * F;
        slope.add(error_in_eps(wavecontact::load_slope(params, p.a), dPda), p);
      }
    }
  }
  check(load);
  check(ratio);
  check(slope);
}

// The pressure beyond b1/2 in closed form (derive/formulas/beyond_branch.hpp: eq. 12 split at the kink,
// J_{j,l} atoms) against the derived v-form at 40 digits (s = tan^2(pi x/(2 b1)) and
// alpha = tan(pi a/(2 b1)) from the exact inputs), over m from 0 to 1e4, a from just above
// b1/2 to b1 and x across the zone: at the centre, next to the kink x = b1/2 on either side,
// around the other branch's pole (cos(pi x/b1) = +-1/m), where the runtime changes forms, at
// the edge, and at 16 points spread over the zone. Beyond b1/2 the pressure of one zone may
// change sign (it is then not the contact, see LoadCurve), so the error is taken relative to the
// largest |p| of the zone's points. The array form is measured too, with those points among
// 4000 spread over the zone, so that it tabulates the Cauchy part's atoms (CauchyAtomTable) over
// most of them, and so is a WavinessZone's point, which reads them from the panels it builds.
BOOST_AUTO_TEST_CASE(pressure_beyond_half_within_64_eps) {
  wavecontact::test::Precision precision(wavecontact::test::reference_digits);
  const auto& beyond = waviness().beyond_half;
  ErrorReport top{"pressure, a > b1/2, |x| < b1/2"}, flank{"pressure, a > b1/2, |x| > b1/2"};
  ErrorReport array_top{"pressure (array), a > b1/2, |x| < b1/2"},
      array_flank{"pressure (array), a > b1/2, |x| > b1/2"};
  ErrorReport zone_top{"pressure (WavinessZone), a > b1/2, |x| < b1/2"},
      zone_flank{"pressure (WavinessZone), a > b1/2, |x| > b1/2"};
  const std::vector<std::array<double, 3>> scales{{1, 1, 1}, {2.5e9, 1e-3, 10}, {7, 0.3, 3.7}};
  std::size_t k = 0;
  for (double m : {0.0, 1e-3, 0.2, 0.5, 0.99, 1.0, 1.01, 2.0, 10.0, 35.0, 100.0, 1e3, 1e4}) {
    for (double fa : {0.5000001, 0.501, 0.55, 0.6, 0.75, 0.9, 0.99, 0.9999}) {
      const auto& [E, H1, b1] = scales[k++ % scales.size()];
      const double a = fa * b1;
      std::vector<double> xs{0,
                             0.2 * b1,
                             0.45 * b1,
                             0.5 * b1 * (1 - 1e-3),
                             0.5 * b1 * (1 - 1e-9),
                             std::nextafter(0.5 * b1, 0.0),
                             std::nextafter(0.5 * b1, b1),
                             0.5 * b1 * (1 + 1e-9),
                             0.5 * b1 * (1 + 1e-3),
                             (0.5 + fa) / 2 * b1,
                             a * (1 - 1e-6),
                             a * (1 - 1e-12)};
      if (m > 1) {  // around the other branch's pole, cos(pi x/b1) = +-1/m
        for (double side : {1.0, -1.0}) {
          for (double shift : {0.0, 1e-6, -1e-6, 0.1, -0.1, 0.2, -0.2}) {
            const double x = std::acos(side / m * (1 + shift)) / M_PI * b1;
            if (std::isfinite(x) && x < a) xs.push_back(x);
          }
        }
      }
      for (int i = 0; i < 16; ++i) xs.push_back(a * (i + 0.37) / 16);
      const wavecontact::WavinessParams params{H1, b1, m, E};
      std::vector<std::pair<PhysicalPoint, GiNaC::numeric>> references;
      GiNaC::numeric scale = 0;
      for (double x : xs) {
        if (!(x < a) || x == 0.5 * b1) continue;
        const PhysicalPoint p{E, H1, b1, m, a, x};
        const auto& side = x < 0.5 * b1 ? beyond.pressure_top_v : beyond.pressure_flank_v;
        const GiNaC::ex p_x = wavecontact::derive::as_ex(side.own) + wavecontact::derive::as_ex(side.other_cauchy);
        references.emplace_back(p, GiNaC::ex_to<GiNaC::numeric>(p_x.subs(p.v_variables()).evalf()));
        scale = std::max(scale, GiNaC::abs(references.back().second));
      }
      Eigen::ArrayXd spread(4000 + references.size());
      for (int i = 0; i < 4000; ++i) spread[i] = a * (i + 0.5) / 4000;
      for (std::size_t i = 0; i < references.size(); ++i)
        spread[4000 + static_cast<Eigen::Index>(i)] = references[i].first.x;
      const Eigen::ArrayXd array = wavecontact::pressure(params, a, spread);
      const wavecontact::WavinessZone zone(params, a);
      for (std::size_t i = 0; i < references.size(); ++i) {
        const auto& p = references[i].first;
        const auto& reference = references[i].second;  // a structured binding cannot be captured (C++17)
        const auto error = [&](double got) {
          return (GiNaC::abs(wavecontact::test::exact(got) - reference) / scale).to_double() / 2.220446049250313e-16;
        };
        (p.x < 0.5 * b1 ? top : flank).add(error(wavecontact::pressure(params, a, p.x)), p);
        (p.x < 0.5 * b1 ? array_top : array_flank).add(error(array[4000 + static_cast<Eigen::Index>(i)]), p);
        (p.x < 0.5 * b1 ? zone_top : zone_flank).add(error(zone.pressure(p.x)), p);
      }
    }
  }
  check(top);
  check(flank);
  check(array_top);
  check(array_flank);
  check(zone_top);
  check(zone_flank);
}

// Full contact of eq. 2 (the built-in profile parametric_wave_curve, built with abs()) in closed
// form, against a derived form at 40 digits (tests/full_contact_test.cpp proves them equal to the
// conjugate's quadrature), relative to the largest |p_fc|: next to the branch point b1/2, next to
// the poles of the other branch's formula (cos = +-1/m) and at both ends of the period.
BOOST_AUTO_TEST_CASE(full_contact_of_eq2_within_64_eps) {
  wavecontact::test::Precision precision(wavecontact::test::reference_digits);
  namespace derive = wavecontact::derive;
  const auto specs = derive::example_profiles();
  const auto spec =
      std::find_if(specs.begin(), specs.end(), [](const auto& p) { return p.name == "parametric_wave_curve"; });
  BOOST_TEST_REQUIRE((spec != specs.end()));
  const derive::ProfileDerivation d = derive::derive_profile(*spec);
  ErrorReport top{"full contact, eq. 2, |x| < b1/2"}, flank{"full contact, eq. 2, |x| >= b1/2"};
  const std::vector<std::array<double, 3>> scales{{1, 1, 1}, {2.5e9, 1e-3, 10}, {7, 0.3, 3.7}};
  std::size_t k = 0;
  for (double m : {0.0, 1e-3, 0.2, 0.5, 0.99, 1.0, 1.01, 2.0, 10.0, 35.0, 100.0, 1e3, 1e4}) {
    const auto& [E, H1, b1] = scales[k++ % scales.size()];
    const wavecontact::Profile profile({"parametric_wave_curve", {{"H1", H1}, {"m", m}}, b1, E});
    std::vector<double> xs{0,
                           1e-9 * b1,
                           0.2 * b1,
                           0.45 * b1,
                           0.5 * b1 * (1 - 1e-3),
                           0.5 * b1 * (1 - 1e-9),
                           std::nextafter(0.5 * b1, 0.0),
                           0.5 * b1,
                           std::nextafter(0.5 * b1, b1),
                           0.5 * b1 * (1 + 1e-9),
                           0.5 * b1 * (1 + 1e-3),
                           0.8 * b1,
                           b1 * (1 - 1e-9),
                           b1};
    if (m > 1) {  // the other branch's poles, cos(pi x/b1) = +-1/m
      for (double side : {1.0, -1.0}) {
        for (double shift : {0.0, 1e-9, -1e-9, 1e-6, -1e-6, 1e-3, -1e-3})
          xs.push_back(std::acos(side / m * (1 + shift)) / M_PI * b1);
      }
    }
    std::vector<std::pair<double, GiNaC::numeric>> references;
    GiNaC::numeric scale = 0;
    for (double x : xs) {
      // At the runtime's own Cx: near the branch point and the other branch's poles, p_fc varies on
      // the scale 1/m of cos x^, so that the rounding of x/b1 alone moves it by eps |x dp/dx|, up
      // to 1e5 eps at m = 1e4 (the problem's conditioning in x, not the evaluator's error).
      const GiNaC::numeric Cx = wavecontact::test::exact(boost::math::cos_pi(x / b1));
      // Within 1e-6 of the branch point the side forms' logarithms are large at 40 digits too: the
      // whole form there (the poles of either branch's formula lie at |Cx| = 1/m >= 1e-4).
      const GiNaC::ex& form = GiNaC::abs(Cx) < GiNaC::numeric(1, 1000000) ? d.full_contact_pressure
                              : Cx > 0                                    ? d.full_contact_pressure_top
                                                                          : d.full_contact_pressure_flank;
      const GiNaC::exmap point{{derive::sym::E(), wavecontact::test::exact(E)},
                               {derive::sym::b1(), wavecontact::test::exact(b1)},
                               {d.parameters[0], wavecontact::test::exact(H1)},
                               {d.parameters[1], wavecontact::test::exact(m)},
                               {derive::sym::Cx(), Cx}};
      references.emplace_back(x, GiNaC::ex_to<GiNaC::numeric>(form.subs(point).evalf()));
      scale = std::max(scale, GiNaC::abs(references.back().second));
    }
    for (const auto& [x, reference] : references) {
      const double got = profile.full_contact_pressure(0, x);
      const double error = (GiNaC::abs(wavecontact::test::exact(got) - reference) / scale).to_double();
      (x < 0.5 * b1 ? top : flank).add(error / 2.220446049250313e-16, PhysicalPoint{E, H1, b1, m, b1, x});
    }
  }
  check(top);
  check(flank);
}

BOOST_AUTO_TEST_CASE(inverse_of_load_round_trips) {
  ErrorReport report{"a(P(a))"};
  for (const auto& p : domain_points()) {
    if (p.x != 0) continue;
    const wavecontact::WavinessParams params{p.H1, p.b1, p.m, p.E};
    const double a = wavecontact::single_asperity_half_width(params, wavecontact::load(params, p.a));
    const double relative = std::abs(a - p.a) / p.a;
    report.add(relative / 2.220446049250313e-16, p);
  }
  BOOST_TEST_MESSAGE(report.summary());
  // a(P) is ill-conditioned where P(a) is flat (large m near a = b1/2 it is steep instead):
  // the round trip is held to 1e-12 relative.
  BOOST_TEST(report.max * 2.220446049250313e-16 <= 1e-12, report.summary());
}

namespace {

// The exact roughness pressure at 40 digits (CLN), from the Legendre-Dirichlet form that
// derive/ proves equal to the engine's closed form:
// (pi/b1) (E H2 n/sqrt2) sqrt(cos x^ - cos a^) sum_j P_{n-1-j}(cos a^) cos((j+1/2) x^).
GiNaC::numeric roughness_reference(int n, double E, double H2, double b1, double a, double x) {
  using GiNaC::numeric;
  using wavecontact::test::exact;
  const numeric b = exact(b1);
  const numeric ahat = GiNaC::ex_to<numeric>((GiNaC::Pi * exact(a) / b).evalf());
  const numeric xhat = GiNaC::ex_to<numeric>((GiNaC::Pi * exact(x) / b).evalf());
  const numeric ca = GiNaC::cos(ahat);
  std::vector<numeric> P{1, ca};
  for (int k = 1; k < n; ++k) P.push_back(((2 * k + 1) * ca * P[k] - k * P[k - 1]) / (k + 1));
  numeric sum = 0;
  for (int j = 0; j < n; ++j) sum += P[n - 1 - j] * GiNaC::cos((j + numeric(1, 2)) * xhat);
  const numeric scale =
      GiNaC::ex_to<numeric>((GiNaC::Pi / b * exact(E) * exact(H2) * n / GiNaC::sqrt(numeric(2))).evalf());
  return scale * GiNaC::sqrt(GiNaC::cos(xhat) - ca) * sum;
}

double parse_rational(const std::string& k) {
  const auto slash = k.find('/');
  return slash == std::string::npos ? std::stod(k) : std::stod(k.substr(0, slash)) / std::stod(k.substr(slash + 1));
}

}  // namespace

BOOST_AUTO_TEST_CASE(roughness_within_1e12_of_scale) {
  wavecontact::test::Precision precision(wavecontact::test::reference_digits);
  for (int n : {2, 8, 16, 32, 64, 128, 256}) {
    const double E = 1.5, H2 = 0.02, b1 = 3.0;
    const double scale = E * H2 * n * M_PI / b1;
    double worst = 0, array_worst = 0, naive_worst = 0;
    const Eigen::ArrayXd fractions{{0.0, 0.1, 0.33, 0.6, 0.9, 0.999, 1 - 1e-9}};
    for (double fa : {0.2 / n, 1.0 / n, 0.05, 0.2, 0.35, 0.5}) {
      const double a = fa * b1;
      const wavecontact::TwoScaleContact contact({{1.0, b1, 0.0, E}, {H2, n}}, a);
      const Eigen::ArrayXd xs = fractions * a;
      Eigen::ArrayXd array_path(xs.size());  // the array API (vectorised where the CPU can)
      contact.roughness_pressure(xs, array_path);
      for (Eigen::Index i = 0; i < xs.size(); ++i) {
        const GiNaC::numeric reference = roughness_reference(n, E, H2, b1, a, xs[i]);
        const auto error = [&](double computed) {
          return std::abs((wavecontact::test::exact(computed) - reference).to_double()) / scale;
        };
        worst = std::max(worst, error(contact.roughness_pressure(xs[i])));
        array_worst = std::max(array_worst, error(array_path[i]));
      }
    }
    // For comparison: eq. 18's right-hand side s(v) = sum_j k_j v/(v^2+1)^j summed naively
    // in double, against sin(n x^)/n, over v in (0, 1].
    const auto k = wavecontact::expansion_coefficients(n);
    for (int i = 1; i <= 50; ++i) {
      const double v = i / 50.0, w = 1 / (1 + v * v);
      double sum = 0, power = 1;
      for (const auto& kj : k) power *= w, sum += parse_rational(kj) * v * power;
      naive_worst = std::max(naive_worst, std::abs(sum - std::sin(n * 2 * std::atan(v)) / n));
    }
    BOOST_TEST_MESSAGE("n = " << n << ": roughness pressure max error " << worst << " (array API " << array_worst
                              << ") x E*H2 n pi/b1; naive eq. 18 sum max error " << naive_worst << " (|s(v)| <= 1/n)");
    BOOST_TEST(worst <= 1e-12, "n = " << n << ": " << worst);
    BOOST_TEST(array_worst <= 1e-12, "n = " << n << ", array API: " << array_worst);
  }
}
