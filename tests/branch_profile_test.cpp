// Profiles built with abs() through the runtime (derive/profile/branches.hpp, beyond_branch.hpp),
// derived at build time by wavecontact_generate (tests/CMakeLists.txt):
// - kinked: y = H cos x + c (5 cos x - 3) |5 cos x - 3|, whose branch changes at cos x = 3/5
//   (tan(x/2) = 1/2) with a kink in its slope, against the independent quadrature of kinked_reference.hpp, the load
//   against the quadrature of that pressure, dP/da against a difference, continuity across
//   the branch point, the height on both branches;
// - analytic_wave: eq. 2's top branch alone, y = H1 (m+1) cos x/(m cos x + 1), whose pole
//   at cos x = -1/m bounds the contact (the reach), which eq. 2 itself does not have.
#define BOOST_TEST_MODULE branch_profile
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/minima.hpp>

#include "fourier_reference.hpp"
#include "kinked_reference.hpp"
#include "profile_analytic_wave.hpp"
#include "profile_kinked.hpp"
#include "wavecontact/contact.hpp"
#include "wavecontact/profile.hpp"

namespace tt = boost::test_tools;
using wavecontact::Profile;

namespace {

using boost::math::double_constants::pi;
const double kink = std::acos(0.6);  // x^ where 5 cos x - 3 changes sign

// Normalised: b1 = pi, E* = 1, so x is x^ and p is p^.
Profile kinked(double H, double c) {
  static const bool registered = [] {
    wavecontact::register_profile(wavecontact::generated::kinked_profile_evaluator());
    wavecontact::register_profile(wavecontact::generated::analytic_wave_profile_evaluator());
    return true;
  }();
  (void)registered;
  return Profile({"kinked", {{"H", H}, {"c", c}}, pi, 1.0});
}

// The reference's own view of the profile: y = H C + s c (5C - 3)^2, s = +1 on the top
// (|x| < kink) and -1 beyond; G = -(1/2) y' = (1/2) sin x (H + 10 s c (5 cos x - 3)).
long double reference(long double H, long double c, long double a, long double x) {
  const auto G = [&](long double xi, int s) { return std::sin(xi) * (H + 10 * s * c * (5 * std::cos(xi) - 3)) / 2; };
  const auto G_prime = [&](long double xi, int s) {
    const long double sine = std::sin(xi);
    return (std::cos(xi) * (H + 10 * s * c * (5 * std::cos(xi) - 3)) - 50 * s * c * sine * sine) / 2;
  };
  return kinked_reference_pressure(G, G_prime, kink, a, x);
}

}  // namespace

BOOST_AUTO_TEST_CASE(pressure_agrees_with_an_independent_quadrature) {
  double worst = 0;
  for (double c : {0.05, 0.2, 0.5}) {
    const Profile profile = kinked(1.0, c);
    for (double a : {0.8 * kink, 0.999 * kink, 1.001 * kink, 0.5 * pi, 0.8 * pi, 0.97 * pi}) {
      for (double fx : {0.0, 0.3, 0.6, 0.9, 0.999, kink / a * (1 - 1e-7), kink / a * (1 + 1e-7), kink / a * 1.1}) {
        if (fx >= 1) continue;
        const double x = fx * a;
        const double got = profile.pressure(a, x), expected = static_cast<double>(reference(1, c, a, x));
        const double error = std::fabs(got - expected) / std::fabs(expected);
        worst = std::max(worst, error);
        BOOST_TEST(error < 1e-10,
                   "c = " << c << ", a = " << a << ", x = " << x << ": got " << got << ", expected " << expected);
      }
    }
  }
  BOOST_TEST_MESSAGE("kinked profile: largest relative difference from the reference " << worst);
}

// Eq. 6 against the quadrature of the pressure (x = a sin(phi), split at the kink), and
// dP/da against a central difference; load and slope continuous across the branch point.
BOOST_AUTO_TEST_CASE(load_and_slope_beyond_the_branch_point) {
  for (double c : {0.05, 0.2, 0.5}) {
    const Profile profile = kinked(1.0, c);
    for (double a : {0.5 * kink, 1.2 * kink, 0.6 * pi, 0.9 * pi}) {
      const auto integrand = [&](double phi) { return 2 * profile.pressure(a, a * std::sin(phi)) * a * std::cos(phi); };
      using Rule = boost::math::quadrature::gauss_kronrod<double, 31>;
      const double split = a > kink ? std::asin(kink / a) : pi / 4;
      const double quadrature =
          Rule::integrate(integrand, 0, split, 8, 1e-13) + Rule::integrate(integrand, split, pi / 2, 8, 1e-13);
      // The pressure's slope is log-singular at the kink, which limits this quadrature.
      BOOST_TEST(profile.load(a) == quadrature, tt::tolerance(2e-10));
      const double h = 1e-5 * a;
      const double difference = (profile.load(a + h) - profile.load(a - h)) / (2 * h);
      BOOST_TEST(profile.load_slope(a) == difference, tt::tolerance(1e-7));
    }
    // Across the branch point P is continuous and dP/da too, with a square-root onset (the
    // jump of g' enters the flank piece's moment like sqrt(a - a_branch)).
    for (double offset : {1e-9, 1e-6}) {
      const double below = kink * (1 - offset), above = kink * (1 + offset);
      const double P = profile.load(kink), slope = profile.load_slope(kink);
      BOOST_TEST(std::fabs(profile.load(above) - profile.load(below)) <=
                     1e-10 * std::fabs(P) + 2 * std::fabs(slope) * (above - below),
                 "c = " << c << ", offset " << offset);
      BOOST_TEST(
          std::fabs(profile.load_slope(above) - profile.load_slope(below)) <= 20 * std::sqrt(offset) * std::fabs(slope),
          "c = " << c << ", offset " << offset << ": " << profile.load_slope(above) << " vs "
                 << profile.load_slope(below));
    }
    BOOST_TEST(std::isfinite(profile.load(pi)));  // full contact
    BOOST_TEST(profile.reach() == pi);
  }
}

BOOST_AUTO_TEST_CASE(height_on_both_branches) {
  const wavecontact::ProfileEvaluator e = wavecontact::profile_evaluator("kinked");
  const double q[] = {0.7, 0.5};
  for (double x : {0.0, 0.5, kink - 1e-9, kink + 1e-9, 1.5, 2.5, pi}) {
    const double C = std::cos(x);
    const double y = 0.7 * C + 0.5 * (5 * C - 3) * std::fabs(5 * C - 3);
    const double slope = 0.7 + 10 * 0.5 * std::fabs(5 * C - 3);
    BOOST_TEST(e.height(q, C) == y, tt::tolerance(1e-13));
    BOOST_TEST(e.height_slope(q, C) == slope, tt::tolerance(1e-13));
  }
}

BOOST_AUTO_TEST_CASE(pole_bounds_the_reach) {
  kinked(1, 1);  // registers
  // y = H1 (m+1) cos x/(m cos x + 1) has a pole where cos x = -1/m (m > 1).
  for (double m : {0.5, 2.0, 10.0}) {
    const Profile profile({"analytic_wave", {{"H1", 1.0}, {"m", m}}, 10.0, 1.0});
    const double expected = m > 1 ? 10.0 / pi * std::acos(-1 / m) : 10.0;
    BOOST_TEST(profile.reach() == expected, tt::tolerance(1e-14));
    if (m > 1) {
      BOOST_CHECK_THROW(profile.pressure(expected * (1 + 1e-9), 0), std::domain_error);
      BOOST_CHECK_THROW(profile.load(expected), std::domain_error);
    }
    // Eq. 2 itself changes branch at b1/2 before the pole: it reaches full contact.
    BOOST_TEST(Profile({"parametric_wave_curve", {{"H1", 1.0}, {"m", m}}, 10.0, 1.0}).reach() == 10.0);
  }
}

// Full contact in closed form (derive/formulas/full_contact.hpp) against the cosine coefficients of the
// profile (fourier_reference.hpp); a pole on the period has none.
BOOST_AUTO_TEST_CASE(full_contact_of_a_rational_profile) {
  kinked(1, 1);  // registers
  const double b1 = 10, E = 2, P = 3;
  for (double m : {0.0, 0.3, 0.5, 0.8}) {
    const Profile profile({"analytic_wave", {{"H1", 0.7}, {"m", m}}, b1, E});
    const auto y = [&](long double x) { return 0.7L * (m + 1) * std::cos(x) / (m * std::cos(x) + 1); };
    double worst = 0, scale = 0;
    for (double x : {0.0, 1.0, 3.0, 5.0, 7.5, 10.0, -4.0}) {
      const double expected =
          P / (2 * b1) + E / 2 * pi / b1 * static_cast<double>(fourier_slope_sum(y, pi * x / b1, 512));
      worst = std::max(worst, std::fabs(profile.full_contact_pressure(P, x) - expected));
      scale = std::max(scale, std::fabs(expected));
    }
    BOOST_TEST_MESSAGE("analytic_wave, m = " << m << ": full contact within " << worst / scale << " of max |p|");
    BOOST_TEST(worst <= 1e-13 * scale, "m = " << m << ": " << worst / scale);
  }
  const Profile pole({"analytic_wave", {{"H1", 1.0}, {"m", 2.0}}, b1, E});
  BOOST_CHECK_THROW(pole.full_contact_pressure(P, 0), std::domain_error);
  BOOST_CHECK_THROW(kinked(1, 0.2).full_contact_pressure(-1, 0), std::domain_error);
}

// The closed form against the multi-zone contact solver (contact.hpp), which finds full
// contact numerically (Chebyshev panels over the period, split at a branch point): the onset
// -2 b1 min p_fc and the pressure above it; for a rational profile and for profiles built with
// abs() (eq. 2 on either side of m = 1, where the top's pole passes through infinity and beyond
// which each branch's formula has a pole on the other piece, and a kinked user profile).
BOOST_AUTO_TEST_CASE(full_contact_agrees_with_the_contact_solver) {
  kinked(1, 1);  // registers
  for (const Profile& profile :
       {Profile({"analytic_wave", {{"H1", 0.7}, {"m", 0.5}}, 10.0, 2.0}),
        Profile({"parametric_wave_curve", {{"H1", 0.7}, {"m", 0.5}}, 10.0, 2.0}),
        Profile({"parametric_wave_curve", {{"H1", 0.7}, {"m", 3.0}}, 10.0, 2.0}), kinked(1, 0.2)}) {
    const std::string name = profile.params().name;
    const double b1 = profile.params().b1;
    const wavecontact::Surface surface(profile);
    const auto p_fc = [&](double x) { return profile.full_contact_pressure(0, x); };
    double x_min = 0, lowest = p_fc(0);  // the lowest p_fc: on a grid, then refined
    for (int i = 1; i <= 200; ++i) {
      if (p_fc(b1 * i / 200) < lowest) lowest = p_fc(b1 * i / 200), x_min = b1 * i / 200;
    }
    const double onset =
        -2 * b1 *
        boost::math::tools::brent_find_minima(p_fc, std::max(0.0, x_min - b1 / 200), std::min(b1, x_min + b1 / 200), 52)
            .second;
    BOOST_TEST(wavecontact::full_contact_load(surface) == onset, name << ": " << tt::tolerance(1e-9));
    const double P = 1.5 * onset;
    const wavecontact::Contact contact = wavecontact::solve_contact(surface, P);
    BOOST_TEST_REQUIRE(contact.full_contact());
    double worst = 0;
    for (int i = 0; i <= 100; ++i) {
      const double x = -b1 + 2 * b1 * i / 100;
      worst = std::max(worst, std::fabs(contact.pressure(x) - profile.full_contact_pressure(P, x)));
    }
    BOOST_TEST_MESSAGE(name << " full contact: solver vs closed form " << worst / contact.max_pressure());
    BOOST_TEST(worst <= 1e-12 * contact.max_pressure(), name << ": " << worst / contact.max_pressure());
  }
}

// Full contact of profiles built with abs() through the runtime (the adapter's choice of form,
// the scaling by b1 and E) against the cosine coefficients of the profile: their sum k y_k
// converges like 1/N only (y'' jumps at the branch point), so this checks the wiring to 3e-5;
// the digits are measured in tests/accuracy_test.cpp and proven in tests/full_contact_test.cpp.
BOOST_AUTO_TEST_CASE(full_contact_of_profiles_built_with_abs) {
  kinked(1, 1);  // registers
  const double b1 = 10, E = 2;
  for (double m : {0.5, 3.0}) {
    const Profile eq2({"parametric_wave_curve", {{"H1", 0.7}, {"m", m}}, b1, E});
    const auto y = [&](long double x) { return 0.7L * (m + 1) * std::cos(x) / (m * std::fabs(std::cos(x)) + 1); };
    double worst = 0, scale = 0;
    for (double x : {0.0, 1.0, 3.0, 4.9, 5.0, 5.1, 7.5, 10.0, -4.0}) {
      const double expected = E / 2 * pi / b1 * static_cast<double>(fourier_slope_sum(y, pi * x / b1, 4096));
      worst = std::max(worst, std::fabs(eq2.full_contact_pressure(0, x) - expected));
      scale = std::max(scale, std::fabs(expected));
    }
    BOOST_TEST_MESSAGE("eq. 2, m = " << m << ": full contact within " << worst / scale << " of max |p| of the sum");
    BOOST_TEST(worst <= 3e-5 * scale, "m = " << m << ": " << worst / scale);
  }
  const Profile profile = kinked(1, 0.2);  // b1 = pi, E* = 1
  const auto y = [](long double x) {
    return std::cos(x) + 0.2L * (5 * std::cos(x) - 3) * std::fabs(5 * std::cos(x) - 3);
  };
  double worst = 0, scale = 0;
  for (double x : {0.0, 0.5, kink, 1.5, 2.5, pi}) {
    const double expected = static_cast<double>(fourier_slope_sum(y, x, 4096)) / 2;
    worst = std::max(worst, std::fabs(profile.full_contact_pressure(0, x) - expected));
    scale = std::max(scale, std::fabs(expected));
  }
  BOOST_TEST_MESSAGE("kinked: full contact within " << worst / scale << " of max |p| of the sum");
  BOOST_TEST(worst <= 3e-5 * scale, worst / scale);
}
