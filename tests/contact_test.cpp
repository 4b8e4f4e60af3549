// The multi-zone contact solver (wavecontact/contact.hpp), without the BEM oracle
// (contact_oracle_test.cpp has that):
// - where one zone per period is the solution, the closed forms of the wave curve (both
//   regimes), the two-scale profile and a user profile, to 1e-10;
// - full contact against p = P/(2 pi) + (E*/2) sum |k| y_k e^(ikx) (docs/mathematics.md fact 11) and its
//   onset loads;
// - the gap of single zones (docs/mathematics.md fact 10, the measurements);
// - the conditions of a contact at multi-zone loads: p >= 0 on the zones and 0 at their
//   ends, gap >= 0 off them and 0 at both ends of every gap, the zones' loads adding to P;
// - geometric convergence in the nodes per zone, and an error estimate that bounds the
//   error; a sweep agreeing with single solves; validation.
// The loads that once failed, each with what mended it, are contact_regression_test.cpp's.
#define BOOST_TEST_MODULE contact
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/minima.hpp>

#include "contact_checks.hpp"
#include "wavecontact/contact.hpp"
#include "wavecontact/errors.hpp"
#include "wavecontact/stability.hpp"
#include "wavecontact/two_scale.hpp"
#include "wavecontact/waviness.hpp"

namespace tt = boost::test_tools;
using namespace wavecontact;
using wavecontact::test::check_contact;

namespace {

using boost::math::double_constants::pi;

// The seed's Fig. 7 parameters (H1 = 1, b1 = 10, E* = 1) with a roughness harmonic.
TwoScaleParams fig7(double m, double H2, int n) { return {{1.0, 10.0, m, 1.0}, {H2, n}}; }

// The largest |p_solver - p_expected| over points of [0, a), relative to the largest p: up
// to a(1 - 1e-4), since within d of the end p ~ sqrt(a - x) turns an end that differs by
// 1e-15 a (rounding) into differences of 1e-15 a/sqrt(d a) of the pressure scale.
template <typename Expected>
double pressure_difference(const Contact& c, double a, Expected expected) {
  double worst = 0, scale = 0;
  for (int i = 0; i <= 64; ++i) {
    const double x = a * (i < 60 ? i / 60.0 : 1 - std::pow(10.0, -(i - 60)));
    worst = std::max(worst, std::fabs(c.pressure(x) - expected(x)));
    scale = std::max(scale, std::fabs(expected(x)));
  }
  return worst / scale;
}

}  // namespace

BOOST_AUTO_TEST_CASE(wave_curve_single_zone_is_the_closed_form) {
  double worst_end = 0, worst_p = 0;
  for (double m : {0.0, 0.2, 2.0, 10.0, 100.0}) {
    for (double b1 : {1.0, 10.0}) {
      const WavinessParams w{0.7, b1, m, 2.5};
      for (double r : {0.02, 0.2, 0.45}) {
        const double a = r * b1, P = load(w, a);
        const Contact c = solve_contact(Surface(w), P);
        BOOST_TEST_REQUIRE(c.zones_per_period() == 1, "m = " << m << ", a = " << a);
        const double end = std::fabs(c.zones()[0].x_end - a) / b1;
        const double dp = pressure_difference(c, a, [&](double x) { return pressure(w, a, x); });
        BOOST_TEST(end < 1e-12, "m = " << m << ", b1 = " << b1 << ", a = " << a << ": end off by " << end);
        BOOST_TEST(dp < 1e-10, "m = " << m << ", b1 = " << b1 << ", a = " << a << ": p off by " << dp);
        BOOST_TEST(std::fabs(c.zones()[0].load - P) < 1e-12 * P);
        worst_end = std::max(worst_end, end), worst_p = std::max(worst_p, dp);
      }
    }
  }
  BOOST_TEST_MESSAGE("wave curve, a <= b1/2: zone end " << worst_end << " of b1, pressure " << worst_p << " of max p");
}

// Beyond b1/2 the single zone is the contact while the valley stays open: m = 0.5 all the
// way to full contact, m = 1 up to a = 0.6 b1; there the exact solution is the runtime's
// quadrature (docs/mathematics.md fact 8). For m = 2 the valley closes at a = 0.5015 b1: docs/mathematics.md's check
// value at a = 0.6 b1 (p(0) = 0.888) is a single zone of the family that interpenetrates,
// and the contact at its load has two zones.
// A zone across the kink at b1/2 ends where rounding decides it to a few 1e-12 pi: scaling
// its kink correction's potential by 1 +- 1e-15 to 1 +- 1.6e-14 moved the end at m = 0.5,
// a = 0.9 pi anywhere within 2.8e-12 pi of a, and at m = 1, a = 0.58 pi within 1.1e-12 pi;
// quadrature rules for that potential, all as accurate as tanh-sinh, moved it up to
// 4.1e-12 pi (2026-11-29).
BOOST_AUTO_TEST_CASE(wave_curve_single_zone_beyond_half_period) {
  for (const auto& [m, r] : std::vector<std::pair<double, double>>{{0.5, 0.7}, {0.5, 0.9}, {1.0, 0.58}}) {
    const WavinessParams w{1.0, pi, m, 1.0};
    const double a = r * pi, P = load(w, a);
    const Contact c = solve_contact(Surface(w), P);
    BOOST_TEST_REQUIRE(c.zones_per_period() == 1, "m = " << m);
    const double end = std::fabs(c.zones()[0].x_end - a);
    BOOST_TEST(end < 1e-11 * pi, "m = " << m << ", a = " << a << ": end off by " << end / pi << " pi");
    BOOST_TEST(pressure_difference(c, a, [&](double x) { return pressure(w, a, x); }) < 1e-10,
               "m = " << m << ", a = " << a);
  }
  const WavinessParams w{1.0, pi, 2.0, 1.0};
  const double P = load(w, 0.6 * pi);
  BOOST_TEST(P == 3.0393833648235, tt::tolerance(1e-12));
  BOOST_TEST(pressure(w, 0.6 * pi, 0) == 0.88807859551843, tt::tolerance(1e-12));
  const SingleZoneCheck family = single_zone_check(Surface(w), 0.6 * pi);
  BOOST_TEST(!family.solution);
  BOOST_TEST(family.x_of_lowest_gap == pi, tt::tolerance(1e-6));  // the valley
  BOOST_TEST(solve_contact(Surface(w), P).zones_per_period() == 2);
}

BOOST_AUTO_TEST_CASE(two_scale_single_zone_is_the_closed_form) {
  for (int n : {8, 16, 64}) {
    const TwoScaleParams p = fig7(0, 0.02, n);
    // A load whose single zone is admissible (the roughness peaks in it stay in contact).
    const double a = 0.1 * 10 / n;
    const TwoScaleContact closed(p, a);
    BOOST_TEST_REQUIRE(closed.admissible());
    const Contact c = solve_contact(Surface(p), closed.load());
    BOOST_TEST_REQUIRE(c.zones_per_period() == 1, "n = " << n);
    BOOST_TEST(std::fabs(c.zones()[0].x_end - a) < 1e-10 * 10, "n = " << n);
    BOOST_TEST(pressure_difference(c, a, [&](double x) { return closed.pressure(x); }) < 1e-10, "n = " << n);
  }
}

BOOST_AUTO_TEST_CASE(profile_single_zone_is_the_closed_form) {
  const Profile profile({"two_harmonic", {{"H1", 1.0}, {"H3", 0.05}}, 10.0, 2.0});
  for (double a : {1.0, 3.0}) {
    const Contact c = solve_contact(Surface(profile), profile.load(a));
    BOOST_TEST_REQUIRE(c.zones_per_period() == 1);
    BOOST_TEST(std::fabs(c.zones()[0].x_end - a) < 1e-10 * 10);
    BOOST_TEST(pressure_difference(c, a, [&](double x) { return profile.pressure(a, x); }) < 1e-10);
  }
}

// Full contact of a trigonometric polynomial: p = P/(2 b1) + (pi E*/(2 b1)) sum_k k H_k cos(k pi x/b1).
BOOST_AUTO_TEST_CASE(full_contact_is_the_fourier_solution) {
  const TwoScaleParams p = fig7(0, 0.15, 8);
  const double P = 3.5 * pi;  // pa/p* = 3.5, above the onset
  const Contact c = solve_contact(Surface(p), P);
  BOOST_TEST_REQUIRE(c.full_contact());
  BOOST_TEST(c.zones_per_period() == 1);
  BOOST_TEST(c.contact_fraction() == 1.0);
  double worst = 0;
  for (int i = 0; i <= 200; ++i) {
    const double x = -10 + 20.0 * i / 200, q = pi * x / 10;
    const double expected = P / 20 + pi / 20 * (std::cos(q) + 8 * 0.15 * std::cos(8 * q));
    worst = std::max(worst, std::fabs(c.pressure(x) - expected) / c.max_pressure());
  }
  BOOST_TEST(worst < 1e-12, "full contact pressure off by " << worst);
  // Onset: min p = 0, P_fc = -pi min_q (cos q + 8 H2 cos 8q), the minimum near q = 7 pi/8.
  const auto [q_min, lowest] = boost::math::tools::brent_find_minima(
      [](double q) { return std::cos(q) + 8 * 0.15 * std::cos(8 * q); }, 0.8 * pi, pi, 52);
  BOOST_TEST(q_min > 0.8 * pi);
  BOOST_TEST(full_contact_load(Surface(p)) == -pi * lowest, tt::tolerance(1e-10));
}

// Full contact keeps its digits over a range of roughnesses: the series stops where it is
// resolved, its rounding about 1e-13 of max p at n = 32 (72 terms d_j = j G_j, each j eps).
// Taken to its cap of 4096 nodes, the rounding of the high terms put p 1.3e-12 of max p off
// at H2 = 0.0043, n = 8.
BOOST_AUTO_TEST_CASE(full_contact_pressure_within_rounding) {
  double worst = 0;
  for (const int n : {8, 32}) {
    for (int i = 0; i < 25; ++i) {
      const double H2 = 0.002 * std::pow(10.0, i / 24.0);
      const Surface surface(fig7(0, H2, n));
      const double P = 1.1 * full_contact_load(surface);
      const Contact c = solve_contact(surface, P);
      BOOST_TEST_REQUIRE(c.full_contact());
      for (int k = 0; k <= 64; ++k) {
        const double x = 10.0 * k / 64, q = pi * x / 10;
        const double expected = P / 20 + pi / 20 * (std::cos(q) + n * H2 * std::cos(n * q));
        const double off = std::fabs(c.pressure(x) - expected) / c.max_pressure();
        if (off > worst) BOOST_TEST_MESSAGE("n = " << n << ", H2 = " << H2 << ", x = " << x << ": off by " << off);
        worst = std::max(worst, off);
      }
    }
  }
  BOOST_TEST(worst < 3e-13, "full contact pressure off by " << worst << " of its largest");
}

// docs/mathematics.md fact 11 / the issue: onset of full contact of the wave curve, pa/p*.
BOOST_AUTO_TEST_CASE(full_contact_onset_of_the_wave_curve) {
  const std::vector<std::pair<double, double>> onset{{0.0, 1.0},   {0.7, 0.878},  {1.0, 0.891},
                                                     {2.0, 1.154}, {10.0, 3.975}, {35.0, 12.97}};
  for (const auto& [m, ratio] : onset) {
    const WavinessParams w{1.0, 10.0, m, 1.0};
    const double got = full_contact_load(Surface(w)) / (pi * w.E * w.H1);
    BOOST_TEST(got == ratio, tt::tolerance(ratio == 1.0 ? 1e-12 : 6e-4));
    BOOST_TEST_MESSAGE("m = " << m << ": full contact from pa/p* = " << got);
  }
}

// docs/mathematics.md fact 10 and the measurements: single zones that interpenetrate.
BOOST_AUTO_TEST_CASE(single_zone_gap) {
  const Surface s8(fig7(0, 0.15, 8));
  BOOST_TEST(single_zone_check(s8, 0.3).solution);
  const SingleZoneCheck a05 = single_zone_check(s8, 0.5);
  BOOST_TEST(!a05.solution);
  BOOST_TEST(a05.lowest_pressure >= 0.0);
  BOOST_TEST(a05.lowest_gap == -0.0304, tt::tolerance(0.02));
  BOOST_TEST(a05.x_of_lowest_gap == 2.32, tt::tolerance(0.02));
  BOOST_TEST(single_zone_check(s8, 0.9).lowest_gap == -0.25, tt::tolerance(0.02));
  BOOST_TEST(single_zone_check(s8, 3.4).lowest_gap == -0.22, tt::tolerance(0.03));
  BOOST_TEST(single_zone_check(Surface(fig7(0, 0.15, 16)), 0.2).lowest_gap == -0.13, tt::tolerance(0.05));
}

BOOST_AUTO_TEST_CASE(multi_zone_contacts_are_contacts) {
  const Contact snap = solve_contact(Surface(WavinessParams{1, 10, 10, 1}), 1.9 * pi);
  BOOST_TEST(snap.zones_per_period() == 2);  // the top and the valley
  BOOST_TEST(snap.zones().back().x_end > 10.0);
  check_contact(snap, 10, "m = 10, pa/p* = 1.9");
  const Contact rough = solve_contact(Surface(fig7(0, 0.15, 8)), 0.1 * pi);
  BOOST_TEST(rough.zones_per_period() == 3);
  check_contact(rough, 10, "n = 8, pa/p* = 0.1");
  const Contact rough16 = solve_contact(Surface(fig7(10, 0.15, 16)), 0.3 * pi);
  BOOST_TEST(rough16.zones_per_period() > 3);
  check_contact(rough16, 10, "m = 10, n = 16, pa/p* = 0.3");
  const Profile dimple({"two_harmonic", {{"H1", 1.0}, {"H3", -0.2}}, 10.0, 1.0});
  const Contact dimpled = solve_contact(Surface(dimple), 0.05);
  BOOST_TEST(dimpled.zones_per_period() == 2);  // two tops either side of x = 0
  BOOST_TEST(dimpled.pressure(0) == 0.0);
  check_contact(dimpled, 10, "two_harmonic, H3 = -0.2");
}

// The commands: two zones at pa/p* = 1.9 for m = 10, full contact at 4.5 (beyond
// the onset 3.975). The single zone's load peaks at pa/p* = 1.80, but the valley closes
// before: from pa/p* = 0.974 (a = 0.4876 b1) the contact is the top and the valley.
BOOST_AUTO_TEST_CASE(snap_through_goes_to_two_zones_then_full_contact) {
  const WavinessParams w{1, 10, 10, 1};
  BOOST_TEST(LoadCurve(w).maximum_load() / pi == 1.80, tt::tolerance(5e-3));
  BOOST_TEST(single_zone_check(Surface(w), 4.87).solution);
  BOOST_TEST(!single_zone_check(Surface(w), 4.88).solution);
  const std::vector<Contact> sweep = solve_contact(Surface(w), {0.97 * pi, 0.98 * pi, 1.9 * pi, 3.9 * pi, 4.5 * pi});
  BOOST_TEST(sweep[0].zones_per_period() == 1);
  BOOST_TEST(sweep[1].zones_per_period() == 2);
  BOOST_TEST(sweep[2].zones_per_period() == 2);
  BOOST_TEST(sweep[3].zones_per_period() == 2);
  BOOST_TEST(sweep[4].full_contact());
  for (std::size_t i = 1; i < sweep.size(); ++i) {
    BOOST_TEST(sweep[i - 1].contact_fraction() < sweep[i].contact_fraction());
  }
}

BOOST_AUTO_TEST_CASE(sweep_equals_single_solves) {
  const Surface s(fig7(0, 0.15, 8));
  const std::vector<double> loads{0.6 * pi, 0.05 * pi, 0.2 * pi};
  const std::vector<Contact> sweep = solve_contact(s, loads);
  for (std::size_t i = 0; i < loads.size(); ++i) {
    const Contact single = solve_contact(s, loads[i]);
    BOOST_TEST_REQUIRE(single.zones_per_period() == sweep[i].zones_per_period());
    for (std::size_t k = 0; k < single.zones().size(); ++k) {
      BOOST_TEST(std::fabs(single.zones()[k].x_end - sweep[i].zones()[k].x_end) < 1e-10 * 10);
    }
    BOOST_TEST(single.pressure(0) == sweep[i].pressure(0), tt::tolerance(1e-10));
  }
}

// A sweep of small steps starts each load from the contacts at the loads before it
// (extrapolated in the load) and settles the zones that open or merge on the way: 40 loads
// of a rough surface whose zones change in number along the line, and a sweep of uneven
// steps, each a contact and each the single solve's.
BOOST_AUTO_TEST_CASE(fine_sweep_equals_single_solves) {
  const Surface s(fig7(0, 0.02, 32));
  std::vector<double> loads;
  for (int i = 0; i < 40; ++i) loads.push_back((0.2 + 0.02 * i) * pi);
  const std::vector<Contact> sweep = solve_contact(s, loads);
  int fewest = 1000, most = 0;
  for (std::size_t i = 0; i < loads.size(); ++i) {
    const std::string what = "n = 32, pa/p* = " + std::to_string(loads[i] / pi);
    const Contact single = solve_contact(s, loads[i]);
    BOOST_TEST_REQUIRE(single.zones_per_period() == sweep[i].zones_per_period(), what);
    fewest = std::min(fewest, single.zones_per_period()), most = std::max(most, single.zones_per_period());
    for (std::size_t k = 0; k < single.zones().size(); ++k) {
      BOOST_TEST(std::fabs(single.zones()[k].x_end - sweep[i].zones()[k].x_end) < 1e-10 * 10, what);
    }
    BOOST_TEST(single.pressure(0) == sweep[i].pressure(0), tt::tolerance(1e-10));
    check_contact(sweep[i], 10, what);
  }
  BOOST_TEST(most >= fewest + 4);  // zones opened and merged along the sweep
  // Uneven steps: a step 200 times the one before it is not extrapolated so far.
  const std::vector<double> uneven{0.5 * pi, 0.5005 * pi, 0.6 * pi, 0.62 * pi};
  const std::vector<Contact> jumps = solve_contact(s, uneven);
  for (std::size_t i = 0; i < uneven.size(); ++i) {
    const std::string what = "uneven steps, pa/p* = " + std::to_string(uneven[i] / pi);
    const Contact single = solve_contact(s, uneven[i]);
    BOOST_TEST_REQUIRE(single.zones_per_period() == jumps[i].zones_per_period(), what);
    BOOST_TEST(single.pressure(0) == jumps[i].pressure(0), tt::tolerance(1e-10));
    check_contact(jumps[i], 10, what);
  }
}

// Geometric convergence in the nodes per zone, multi-zone cases on smooth profiles: the
// error of the zone ends and of p against an adaptive solve at 1e-12 falls by a factor 10
// at least per 4 more nodes until rounding, and the error estimate bounds the error. p is
// compared short of a tenth of a zone from its ends: near an end p ~ sqrt(b - x) turns an
// end that differs by its rounding (1e-15 of the period) into a difference of p of 1e-12.
// The reference has its own error (its estimate): the floor both reach is their rounding.
BOOST_AUTO_TEST_CASE(convergence_is_geometric) {
  struct Case {
    const char* name;
    Surface surface;
    double P;
  };
  const std::vector<Case> cases{{"n = 8, pa/p* = 0.1 (three zones)", Surface(fig7(0, 0.15, 8)), 0.1 * pi},
                                {"n = 64, pa/p* = 0.5 (35 zones)", Surface(fig7(0, 0.15, 64)), 0.5 * pi}};
  for (const Case& k : cases) {
    const Contact reference = solve_contact(k.surface, k.P, {1e-12});
    std::vector<double> errors;
    for (int nodes : {8, 12, 16, 20, 24}) {
      const Contact c = solve_contact(k.surface, k.P, {1e-10, nodes});
      BOOST_TEST_REQUIRE(c.zones_per_period() == reference.zones_per_period());
      double error = 0;
      for (std::size_t z = 0; z < c.zones().size(); ++z) {
        error = std::max(error, std::fabs(c.zones()[z].x_end - reference.zones()[z].x_end) / 20);
      }
      for (const ContactZone& z : reference.zones()) {
        const double margin = 0.1 * (z.x_end - z.x_start);
        for (int i = 0; i <= 200; ++i) {
          const double x = z.x_start + margin + (z.x_end - z.x_start - 2 * margin) * i / 200;
          error = std::max(error, std::fabs(c.pressure(x) - reference.pressure(x)) / reference.max_pressure());
        }
      }
      errors.push_back(error);
      BOOST_TEST_MESSAGE(k.name << ": " << nodes << " nodes, error " << error << ", estimate " << c.error_estimate());
      BOOST_TEST(error <= c.error_estimate() + reference.error_estimate(), k.name << ", " << nodes << " nodes");
    }
    const double floor = std::max(1e-13, 2 * reference.error_estimate());
    for (std::size_t i = 1; i < errors.size(); ++i) {
      BOOST_TEST(errors[i] < std::max(errors[i - 1] / 10, floor), k.name << ", " << 4 * i + 8 << " nodes");
    }
    // At a tolerance of 1e-12 the estimate is the refinement's floor: each solve meets its rows
    // to 1e-13, and a coefficient errs by up to its index times that (8e-12 to 1.6e-11 at 35
    // zones, as the path to it changes).
    BOOST_TEST(reference.error_estimate() < 3e-11, k.name);
    BOOST_TEST(errors.back() < 1e-11, k.name);
  }
}

// Several harmonics: the waviness with n = 8 and n = 64 roughness, many zones per period.
BOOST_AUTO_TEST_CASE(several_harmonics) {
  const Surface s(WavinessParams{1, 10, 0, 1}, {{0.15, 8}, {0.02, 64}});
  const std::vector<Contact> sweep = solve_contact(s, {0.05 * pi, 0.5 * pi});
  BOOST_TEST(sweep[0].zones_per_period() >= 3);
  BOOST_TEST(sweep[1].zones_per_period() > sweep[0].zones_per_period());
  BOOST_TEST(sweep[1].error_estimate() < 1e-10);
  check_contact(sweep[1], 10, "n = 8 and 64, pa/p* = 0.5");
}

// Many small zones clustered near the top of a flattened wave (m = 2, n = 256): each zone in
// its own basis, the rounding stays at the level of one zone's.
BOOST_AUTO_TEST_CASE(clusters_near_the_top) {
  const Surface s(TwoScaleParams{{1, 10, 2, 1}, {0.02, 256}});
  const Contact c = solve_contact(s, 0.5 * pi);
  BOOST_TEST(c.zones_per_period() > 30);
  BOOST_TEST(c.rounding_error() < 1e-12);
  BOOST_TEST(c.error_estimate() < 1e-10);
  check_contact(c, 10, "m = 2, n = 256, pa/p* = 0.5");
}

// A spent work budget says how far Newton's method got. The caller's checkpoint, called at
// the first safe point (the first Newton iteration: a rough surface starts from its grid),
// outlasts the budget, so the first check stops the solve.
BOOST_AUTO_TEST_CASE(a_spent_budget_names_the_lowest_residual) {
  SolverOptions options(1e-8, 0, 0.05);
  options.checkpoint = [] { std::this_thread::sleep_for(std::chrono::milliseconds(100)); };
  try {
    solve_contact(Surface(fig7(0, 0.15, 16)), 0.3 * pi, options);
    BOOST_ERROR("the solve finished within a spent budget");
  } catch (const BeyondReach& e) {
    const std::string message = e.what();
    BOOST_TEST(message.find("the work budget of 0.05 s (max_seconds) is spent") != std::string::npos, message);
    BOOST_TEST(message.find("the lowest scaled residual Newton's method reached: ") != std::string::npos, message);
    // The load named so that it reads back as the load asked for (not 0.942478).
    const std::size_t at = message.find("solving at P = ");
    BOOST_TEST_REQUIRE(at != std::string::npos, message);
    BOOST_TEST(std::strtod(message.c_str() + at + 15, nullptr) == 0.3 * pi, message);
  }
}

// Beyond the shapes the campaigns vouch for (m <= 35), a load the solver cannot reach is
// refused, never answered with a contact that is none: on the near-square wave m = 796 the
// full contact holds a tension of -84.5 on the wall at b1/2, and the two zones that would open
// a gap there close it again (campaign seed 62, sweep 105; docs/campaigns.md, *Beyond m = 35*).
// Whatever a later solver makes of it, what it returns must be a contact, and a refusal names
// the load.
BOOST_AUTO_TEST_CASE(near_square_wave_beyond_reach_is_refused_not_answered) {
  const Surface s(WavinessParams{1, 10, 796.09932275018775, 1}, {{0.2, 10}, {0.2, 4}});
  try {
    check_contact(solve_contact(s, 457.5116238196093, SolverOptions(1e-10, 0, 120)), 10, "seed 62, sweep 105");
  } catch (const BeyondReach& e) {  // refused: the message names the load
    const std::string message = e.what();
    BOOST_TEST(message.find("P = 457.5116238196093") != std::string::npos, message);
  }
}

BOOST_AUTO_TEST_CASE(invalid_input_is_refused) {
  const Surface s(WavinessParams{1, 10, 2, 1});
  for (double P : {0.0, -1.0, std::nan(""), HUGE_VAL}) {
    BOOST_CHECK_THROW(solve_contact(s, P), std::domain_error);
  }
  try {
    solve_contact(s, -1.0);
  } catch (const std::domain_error& e) {
    const std::string what = e.what();
    BOOST_TEST(what.find("wavecontact::solve_contact: P = -1") != std::string::npos, what);
  }
  BOOST_CHECK_THROW(solve_contact(s, 1.0, {1e-20, 0}), std::domain_error);
  BOOST_CHECK_THROW(solve_contact(s, 1.0, {1e-10, 3}), std::domain_error);
  BOOST_CHECK_THROW(solve_contact(s, 1.0, {1e-10, 4097}), std::domain_error);
  BOOST_CHECK_THROW(Surface(WavinessParams{1, 10, 2, 1}, {{0.1, 0}}), std::domain_error);
  BOOST_CHECK_THROW(Surface(WavinessParams{1, 10, 2, 1}, {{std::nan(""), 4}}), std::domain_error);
  BOOST_CHECK_THROW(single_zone_check(s, 10.0), std::domain_error);
  BOOST_CHECK_THROW(Surface(WavinessParams{1, -10, 2, 1}), std::domain_error);
}
