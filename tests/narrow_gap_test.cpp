// A narrow gap inside a zone (runtime/src/contact/narrow_gap.*), white-box: the inner solution
// of a cubic minimum, and the merged contact with it against the two zones' contact where the
// solver still finds that one.
#define BOOST_TEST_MODULE narrow_gap
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "contact/constants.hpp"
#include "contact/narrow_gap.hpp"
#include "contact/solution.hpp"
#include "contact/zone_system.hpp"
#include "wavecontact/contact.hpp"

using namespace wavecontact;
using detail::NarrowGap;
using detail::pi;

// A merged pressure that is a cubic about its minimum at x0 = 1: -T + kappa xi^2/2 + lambda xi^3/6.
BOOST_AUTO_TEST_CASE(inner_solution_of_a_cubic_minimum) {
  const double T = 4.5e-7, kappa = 1.39e5, lambda = -1.46e5, x0 = 1;
  const auto cubic = [&](double x) {
    const double xi = x - x0;
    return -T + kappa * xi * xi / 2 + lambda * xi * xi * xi / 6;
  };
  const std::optional<NarrowGap> found = detail::narrow_gap(cubic, x0 + 2e-6, 3.5e-6);
  BOOST_TEST_REQUIRE(found.has_value());
  const NarrowGap& g = *found;
  BOOST_TEST(std::fabs(g.x0 - x0) < 1e-15, "x0 " << g.x0 - x0);
  BOOST_TEST(g.T == T, boost::test_tools::tolerance(1e-8));
  BOOST_TEST(g.kappa == kappa, boost::test_tools::tolerance(1e-8));
  BOOST_TEST(g.lambda == lambda, boost::test_tools::tolerance(1e-4));
  // Q R less the cubic, taken directly in long double, against the correction's form free of
  // cancellation (within the shift of the cubic that the centre's rounding to a double makes,
  // kappa |w| ulp); beyond the gap it falls like -B half^4 / (8 w^2).
  const long double A = g.A, B = g.B, D = g.D, c = g.half;
  for (double r : {-300.0, -30.0, -3.0, -1.5, -1.01, 1.01, 1.5, 3.0, 30.0, 300.0}) {
    const double x = g.centre + r * g.half;
    const long double w = static_cast<long double>(x) - g.centre, xi = static_cast<long double>(x) - g.x0;
    const long double R = w * std::sqrt(1 - c * c / (w * w));
    const long double direct =
        (A * w * w + B * w + D) * R - (-g.T + g.kappa * xi * xi / 2 + g.lambda * xi * xi * xi / 6);
    const double got = g.correction(x);
    const double shift = g.kappa * std::fabs(r * g.half) * 2.3e-16 * std::fabs(x);
    BOOST_TEST(std::fabs(got - static_cast<double>(direct)) <= 1e-6 * std::fabs(static_cast<double>(direct)) + shift,
               "w = " << r << " half: " << got << " against " << static_cast<double>(direct));
  }
  const double far = 1e4 * g.half;
  const double tail = -g.B * std::pow(g.half, 4) / (8 * far * far);
  BOOST_TEST(g.correction(g.centre + far) / tail == 1.0, boost::test_tools::tolerance(1e-3));
  // The pressure rises from either edge like |Q| half sqrt(2 (|w| - half) / half); the gap
  // inside is 0 at both and positive between.
  for (double side : {-1.0, 1.0}) {
    const double edge = g.centre + side * g.half, x = g.centre + side * g.half * (1 + 1e-6);
    const double Q = g.A * g.half * g.half + side * g.B * g.half + g.D;
    BOOST_TEST(cubic(x) + g.correction(x) == std::fabs(Q) * g.half * std::sqrt(2e-6),
               boost::test_tools::tolerance(1e-3));
    BOOST_TEST(std::fabs(g.gap(edge, 1.0)) < 1e-14 * g.gap(g.centre, 1.0), "gap at the edge " << g.gap(edge, 1.0));
  }
  for (int i = 1; i < 100; ++i) {
    const double x = g.centre - g.half * std::cos(pi * i / 100);
    BOOST_TEST(g.gap(x, 1.0) > 0, "gap at " << x);
  }
  // The inner solution carries no load of its own: over the gap the pressure loses the cubic,
  // beyond it gains the correction, and the two cancel but for the correction's tail beyond L.
  boost::math::quadrature::tanh_sinh<double> integrator;
  const double L = 1e3 * g.half;
  const double lost = integrator.integrate(cubic, g.centre - g.half, g.centre + g.half, 1e-14);
  const auto correction = [&](double x) { return g.correction(x); };
  const double gained = integrator.integrate(correction, g.centre + g.half, g.centre + L, 1e-14) +
                        integrator.integrate(correction, g.centre - L, g.centre - g.half, 1e-14);
  const double tails = g.B * std::pow(g.half, 4) / (4 * L);
  BOOST_TEST(std::fabs(gained - lost - tails) < 1e-3 * std::fabs(lost), "lost " << lost << ", gained " << gained);
}

// Campaign seed 41, sweep 10 (m = 0, n = 890) at P = 4.0265256, 3e-6 of load before a gap
// beside the top zone closes: the solver's two zones, and the same contact as one merged zone
// with a narrow gap. The inner solution's edges lie within the two zones' error estimate of
// their ends (3.8e-9 and 1.0e-9 in x^, the estimate 2 pi 1.1e-9 = 7.0e-9); the pressures
// agree to 1e-10 of the largest away from the gap and to 5e-10 beside it (2.2e-11 and
// 3.1e-10), the gaps inside to 2 % (1.3 %). The two zones are the contact the narrow gap
// replaces, short of their tolerance 1e-10 (estimate 1.1e-9): their own pressure near the gap, where
// their estimate does not reach, moves by 2e-9 with the tolerance, and their gap inside by
// 0.6 % between the tolerances 1e-9 and 3e-11 (by 3.4 % while the nodes' rounding was
// noise, docs/contact.md).
BOOST_AUTO_TEST_CASE(merged_contact_with_a_narrow_gap_against_the_two_zones) {
  const Surface s(WavinessParams{1, 10, 0, 1}, {{0.00039567298641233453, 890}});
  const double P = 4.0265256, to_x = 10 / pi;
  const Contact two = solve_contact(s, P, SolverOptions(1e-10));
  // The two zones' half period in x^, the top zone and its neighbour merged.
  detail::Configuration merged;
  std::vector<double> zone_ends;
  for (const ContactZone& z : two.zones()) {
    if (z.x_end <= 0) continue;
    zone_ends.push_back(std::max(0.0, z.x_start) / to_x), zone_ends.push_back(std::min(z.x_end / to_x, pi));
  }
  BOOST_TEST_REQUIRE(zone_ends.size() >= 4u);
  const double gap_start = zone_ends[1], gap_end = zone_ends[2];
  merged.zones.push_back({detail::ZoneGeometry(0, zone_ends[3]), std::vector<double>(4096, 0.0)});
  for (std::size_t k = 4; k < zone_ends.size(); k += 2) {
    merged.zones.push_back({detail::ZoneGeometry(zone_ends[k], zone_ends[k + 1]), std::vector<double>(256, 0.0)});
  }
  const detail::ZoneSystem system(*s.model(), P);
  system.relax(merged);
  system.choose_windows(merged);
  merged = system.newton(std::move(merged), 1e-8, {}, true).configuration;
  const detail::ZoneSystem::Result r = system.newton(std::move(merged), 1e-12, {});
  BOOST_TEST_REQUIRE((r.outcome == detail::ZoneSystem::Outcome::converged));
  detail::Configuration with_gap = r.configuration;
  with_gap.narrow_gaps.push_back((gap_start + gap_end) / 2);
  const detail::ContactSolution one(s.model(), with_gap);
  BOOST_TEST_REQUIRE(one.narrow_gaps(0).size() == 1u);
  const NarrowGap& g = one.narrow_gaps(0).front();
  // The ends agree within the two zones' estimate (relative to the period 2 pi).
  const double ends = 2 * pi * two.error_estimate();
  BOOST_TEST(std::fabs(g.centre - g.half - gap_start) < ends, "gap from " << g.centre - g.half - gap_start);
  BOOST_TEST(std::fabs(g.centre + g.half - gap_end) < ends, "gap to " << g.centre + g.half - gap_end);
  const double largest = two.max_pressure();
  const auto pressure = [&](double x) { return one.pressure(x) * pi / 10; };  // p^ to p
  for (double r : {-300.0, -30.0, -5.0, -2.0, -1.2, 1.2, 2.0, 5.0, 30.0, 300.0}) {
    const double x = g.centre + r * g.half;
    BOOST_TEST(std::fabs(pressure(x) - two.pressure(x * to_x)) < 5e-10 * largest,
               "w = " << r << " half: " << pressure(x) << " against " << two.pressure(x * to_x));
  }
  double away = 0;
  for (int i = 0; i <= 2000; ++i) {
    const double x = pi * i / 2000;
    if (std::fabs(x - g.centre) > 1e3 * g.half) away = std::max(away, std::fabs(pressure(x) - two.pressure(x * to_x)));
  }
  BOOST_TEST(away < 1e-10 * largest, "away from the gap " << away);
  for (double r : {-0.5, 0.0, 0.5}) {
    const double x = g.centre + r * g.half;
    BOOST_TEST(std::fabs(one.gap(x) - two.gap(x * to_x)) < 0.02 * two.gap(x * to_x),
               "gap " << one.gap(x) << " against " << two.gap(x * to_x));
  }
}
