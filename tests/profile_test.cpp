// User profiles through the runtime (wavecontact/profile.hpp), issue examples (a) and (b):
// - the built-in wave curve given as an expression (generated/profile_parametric_wave_curve.hpp)
//   reproduces the built-in evaluators to 1e-14;
// - the two-harmonic profile H1 cos x + H3 cos 3x against the independent numerical inversion
//   of eq. 12, its load against the quadrature of its pressure, dP/da against a difference;
// - validation, the pole bound (reach), admissibility and stability on user profiles.
#define BOOST_TEST_MODULE profile
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "wavecontact/numerical_inversion.hpp"
#include "wavecontact/profile.hpp"
#include "wavecontact/stability.hpp"
#include "wavecontact/waviness.hpp"

namespace tt = boost::test_tools;
using wavecontact::Profile;

namespace {

using boost::math::double_constants::pi;

double relative(double got, double expected) {
  return std::fabs(got - expected) / std::max(std::fabs(expected), 1e-300);
}

Profile two_harmonic(double H1, double H3, double b1 = 10, double E = 2) {
  return Profile({"two_harmonic", {{"H1", H1}, {"H3", H3}}, b1, E});
}

}  // namespace

BOOST_AUTO_TEST_CASE(examples_are_built_in) {
  const auto names = wavecontact::available_profiles();
  BOOST_TEST((std::find(names.begin(), names.end(), "two_harmonic") != names.end()));
  BOOST_TEST((std::find(names.begin(), names.end(), "parametric_wave_curve") != names.end()));
  BOOST_TEST(wavecontact::profile_evaluator("two_harmonic").expression == "H1*cos(x)+H3*cos(3*x)");
}

// Example (a): eq. 2 typed as an expression, |cos x| and all, over 0 < a <= b1. Up to b1/2 its
// top branch's closed forms; beyond, the moments of both branches for the load, dP/da and the
// pressure (the same derivation as the built-in, derive/formulas/beyond_branch.hpp), with the profile's
// emitted g choosing the pressure's parts in place of the built-in's |Cx| m.
BOOST_AUTO_TEST_CASE(wave_curve_expression_reproduces_the_built_in) {
  double worst_p = 0, worst_beyond = 0, worst_P = 0, worst_slope = 0;
  for (double m : {0.0, 0.2, 0.5, 1.0, 2.0, 10.0, 35.0, 1e4}) {
    const wavecontact::WavinessParams w{0.7, 4.0, m, 3.0};
    const Profile profile({"parametric_wave_curve", {{"H1", w.H1}, {"m", m}}, w.b1, w.E});
    for (double fa : {0.02, 0.1, 0.25, 0.4, 0.5, 0.5000001, 0.51, 0.6, 0.75, 0.9, 0.99, 0.999, 1.0}) {
      const double a = fa * w.b1;
      worst_P = std::max(worst_P, relative(profile.load(a), wavecontact::load(w, a)));
      worst_slope = std::max(worst_slope, relative(profile.load_slope(a), wavecontact::load_slope(w, a)));
      if (fa == 1.0) continue;
      for (double fx : {0.0, 0.3, 0.6, 0.9, 0.999, 1 - 1e-9}) {
        const double x = fx * a;
        const double got = profile.pressure(a, x), expected = wavecontact::pressure(w, a, x);
        BOOST_TEST_MESSAGE("m = " << m << ", a = " << a << ", x = " << x << ": " << got << " vs built-in " << expected);
        double& worst = fa <= 0.5 ? worst_p : worst_beyond;
        worst = std::max(worst, relative(got, expected));
      }
    }
  }
  BOOST_TEST_MESSAGE("eq. 2 as an expression vs built-in: pressure " << worst_p << " up to b1/2, " << worst_beyond
                                                                     << " beyond; load " << worst_P << ", dP/da "
                                                                     << worst_slope);
  BOOST_TEST(worst_P <= 1e-14);
  BOOST_TEST(worst_slope <= 1e-14);
  BOOST_TEST(worst_p <= 1e-14);
  BOOST_TEST(worst_beyond <= 1e-14);
}

// Example (b): g(v) = -(E/2) y'(x(v)) with y' = -H1 sin x - 3 H3 sin 3x, inverted
// numerically (docs/mathematics.md section 4) at 400 nodes.
BOOST_AUTO_TEST_CASE(two_harmonic_against_numerical_inversion) {
  const double b1 = 10, E = 2;
  double worst = 0;
  for (double H3 : {0.0, 0.05, 0.1, -0.08, 0.3}) {
    const Profile profile = two_harmonic(1.0, H3, b1, E);
    const auto g = [&](double v) {
      const double x = 2 * std::atan(v);
      return E / 2 * (std::sin(x) + 3 * H3 * std::sin(3 * x));
    };
    for (double fa : {0.1, 0.3, 0.6, 0.9}) {
      const double a = fa * b1, alpha = std::tan(pi * a / (2 * b1));
      double deviation = 0, scale = 0;
      for (double fx : {0.0, 0.2, 0.5, 0.8, 0.95, 0.999}) {
        const double x = fx * a, u = std::tan(pi * x / (2 * b1));
        const double numerical = pi / b1 * wavecontact::numerical_inversion(g, alpha, u, 400);
        deviation = std::max(deviation, std::fabs(profile.pressure(a, x) - numerical));
        scale = std::max(scale, std::fabs(numerical));
      }
      BOOST_TEST(deviation / scale <= 1e-12, "H3 = " << H3 << ", a = " << a << ": " << deviation / scale);
      worst = std::max(worst, deviation / scale);
    }
  }
  BOOST_TEST_MESSAGE("two_harmonic vs numerical inversion: max |dp|/max|p| = " << worst);
}

// Eq. 6 against the quadrature of the pressure, and dP/da against a central difference.
BOOST_AUTO_TEST_CASE(two_harmonic_load_and_slope) {
  for (double H3 : {0.0, 0.1, 0.3}) {
    const Profile profile = two_harmonic(1.0, H3);
    for (double a : {1.0, 4.0, 7.5, 9.5}) {
      // x = a sin(phi) removes the square-root edge.
      const auto integrand = [&](double phi) { return 2 * profile.pressure(a, a * std::sin(phi)) * a * std::cos(phi); };
      const double quadrature =
          boost::math::quadrature::gauss_kronrod<double, 61>::integrate(integrand, 0, pi / 2, 10, 1e-14);
      BOOST_TEST(profile.load(a) == quadrature, tt::tolerance(1e-12));
      const double h = 1e-5 * a;
      const double difference = (profile.load(a + h) - profile.load(a - h)) / (2 * h);
      BOOST_TEST(profile.load_slope(a) == difference, tt::tolerance(1e-7));
    }
    // Full contact: the closed form reaches a = b1.
    BOOST_TEST(std::isfinite(profile.load(10.0)));
  }
  // H3 = 0 is Westergaard's sine: P = pi E* H1 sin^2(pi a/(2 b1)).
  const Profile sine = two_harmonic(0.5, 0.0, 10, 2);
  BOOST_TEST(sine.load(3.0) == pi * 2 * 0.5 * std::pow(std::sin(pi * 3.0 / 20), 2), tt::tolerance(1e-14));
}

// Full contact of H1 cos x + H3 cos 3x: p = P/(2 b1) + (E/2)(pi/b1)(H1 cos x + 3 H3 cos 3x).
BOOST_AUTO_TEST_CASE(two_harmonic_full_contact) {
  const double b1 = 10, E = 2, P = 0.4;
  for (double H3 : {0.0, 0.1, -0.2}) {
    const Profile profile = two_harmonic(1.0, H3, b1, E);
    for (double x : {0.0, 1.5, 5.0, 9.9, -3.0, 23.0}) {
      const double c = pi * x / b1;
      const double expected = P / (2 * b1) + E / 2 * pi / b1 * (std::cos(c) + 3 * H3 * std::cos(3 * c));
      BOOST_TEST(profile.full_contact_pressure(P, x) == expected, tt::tolerance(1e-14));
    }
  }
  BOOST_CHECK_THROW(two_harmonic(1.0, 0.1).full_contact_pressure(std::nan(""), 0), std::domain_error);
}

BOOST_AUTO_TEST_CASE(validation_names_what_is_wrong) {
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const std::domain_error& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  const std::string missing = message([] { Profile({"two_harmonic", {{"H1", 1.0}}, 10, 1}); });
  BOOST_TEST(missing.find("needs the parameter \"H3\"") != std::string::npos, missing);
  const std::string unknown = message([] {
    Profile({"two_harmonic", {{"H1", 1.0}, {"H3", 0.1}, {"H5", 0.0}}, 10, 1});
  });
  BOOST_TEST(unknown.find("no parameter \"H5\"") != std::string::npos, unknown);
  const std::string name = message([] { Profile({"no_such", {}, 10, 1}); });
  BOOST_TEST(name.find("two_harmonic") != std::string::npos, name);
  const std::string b1 = message([] { two_harmonic(1, 0.1, -1); });
  BOOST_TEST(b1.find("b1 = -1") != std::string::npos, b1);
  const std::string nan = message([] { Profile({"two_harmonic", {{"H1", NAN}, {"H3", 0.1}}, 10, 1}); });
  BOOST_TEST(nan.find("H1 = nan") != std::string::npos, nan);
  const std::string a = message([] { two_harmonic(1, 0.1).pressure(10.5, 0); });
  BOOST_TEST(a.find("Profile::pressure: a = 10.5") != std::string::npos, a);
}

// H3 < -H1/9 makes x = 0 a local minimum (two bumps): small zones centred there would need
// a negative pressure; a wide zone covering both bumps is admissible.
BOOST_AUTO_TEST_CASE(admissibility_on_a_user_profile) {
  const Profile dimpled = two_harmonic(1.0, -0.2);
  const auto small = wavecontact::admissibility(dimpled, 1.0);
  BOOST_TEST(!small.admissible);
  BOOST_TEST(small.most_negative_x == 0.0);
  BOOST_TEST(small.most_negative_pressure == dimpled.pressure(1.0, 0), tt::tolerance(1e-15));
  BOOST_TEST(wavecontact::admissibility(two_harmonic(1.0, 0.1), 5.0).admissible);
}

// Stability: LoadCurve on a user profile finds the same snap-through range as on the
// built-in curve when both describe the same surface (m = 0.5 has no pole: the expression
// is the whole eq. 2 only where cos x >= 0, so compare the monotone rise), and a monotone
// two-harmonic load has no unstable range.
BOOST_AUTO_TEST_CASE(stability_on_a_user_profile) {
  const wavecontact::LoadCurve rising(two_harmonic(1.0, 0.1));
  BOOST_TEST(rising.unstable_ranges().empty());
  const auto solutions = rising.equilibria(2.0);
  BOOST_TEST_REQUIRE(solutions.size() == 1u);
  BOOST_TEST(solutions[0].stable);
  BOOST_TEST(two_harmonic(1.0, 0.1).load(solutions[0].a) == 2.0, tt::tolerance(1e-13));
  BOOST_TEST(wavecontact::contact_half_width(two_harmonic(1.0, 0.1), 2.0) == solutions[0].a);

  // The dimpled profile: the load has a turning point where the zone spreads over the two
  // bumps; dP/da changes sign there and the curve reports it.
  const Profile dimpled = two_harmonic(1.0, -0.2);
  const wavecontact::LoadCurve curve(dimpled);
  for (const auto& range : curve.unstable_ranges()) {
    BOOST_TEST(dimpled.load_slope((range.begin + range.end) / 2) < 0);
    BOOST_TEST_MESSAGE("dimpled two_harmonic: dP/da < 0 on [" << range.begin << ", " << range.end << "]");
  }
  for (double a = 0.05; a < 9.9; a += 0.05) {
    const bool inside = std::any_of(curve.unstable_ranges().begin(), curve.unstable_ranges().end(),
                                    [&](const auto& r) { return a > r.begin && a < r.end; });
    if (!inside) BOOST_TEST(dimpled.load_slope(a) >= 0, "a = " << a);
  }
}
