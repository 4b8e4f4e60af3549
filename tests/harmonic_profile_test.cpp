// Profiles of high order through the runtime, derived at build time by wavecontact_generate
// (tests/CMakeLists.txt): their cosine sums have the Legendre-Dirichlet form (derive/
// harmonic_part.hpp), summed by wavecontact/detail/harmonic_series.hpp. Checked against an
// independent numerical inversion of eq. 12 in long double (docs/mathematics.md section 4, midpoint rule
// in theta, its own convergence checked by doubling the nodes): the pressure within 1e-12
// of the zone's largest pressure up to order 256, the load against the quadrature of that
// pressure, dP/da against a difference, the height and its slope against the expression.
#define BOOST_TEST_MODULE harmonic_profile
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <boost/math/quadrature/gauss.hpp>

#include "fourier_reference.hpp"
#include "profile_bump64.hpp"
#include "profile_power256.hpp"
#include "profile_two_scale256.hpp"
#include "wavecontact/profile.hpp"

namespace tt = boost::test_tools;
using wavecontact::Profile;

namespace {

const long double pi_l = 3.141592653589793238462643383279502884L;

struct Case {
  std::string name;
  std::map<std::string, double> parameters;
  int order;
  // y(x^) and its derivative in x^, in long double: the reference's own view of the profile.
  std::function<long double(long double)> y, y_prime;
};

std::vector<Case> cases() {
  const double H = 0.8, H1 = 1.0, H2 = 0.004, c = -0.05;
  return {
      {"power256",
       {{"H", H}},
       256,
       [=](long double x) { return H * std::pow(std::cos(x), 256); },
       [=](long double x) { return -256 * H * std::pow(std::cos(x), 255) * std::sin(x); }},
      {"two_scale256",
       {{"H1", H1}, {"H2", H2}},
       256,
       [=](long double x) { return H1 * std::cos(x) + H2 * std::cos(256 * x); },
       [=](long double x) { return -H1 * std::sin(x) - 256 * H2 * std::sin(256 * x); }},
      {"bump64",
       {{"H", H}, {"c", c}},
       64,
       [=](long double x) { return H * std::pow(std::cos(x), 64) + c * std::cos(x) / (2 - std::cos(x)); },
       [=](long double x) {
         const long double q = 2 - std::cos(x);
         return -64 * H * std::pow(std::cos(x), 63) * std::sin(x) - 2 * c * std::sin(x) / (q * q);
       }},
  };
}

Profile profile(const Case& test, double b1, double E) {
  static const bool registered = [] {
    wavecontact::register_profile(wavecontact::generated::power256_profile_evaluator());
    wavecontact::register_profile(wavecontact::generated::two_scale256_profile_evaluator());
    wavecontact::register_profile(wavecontact::generated::bump64_profile_evaluator());
    return true;
  }();
  (void)registered;
  return Profile({test.name, test.parameters, b1, E});
}

// p^(u) of eq. 12 for g(v) = -(E/2) y'(x^(v)), |u| < alpha, in long double:
// sqrt(alpha^2 - u^2) (1/pi) Int_0^pi (g(alpha cos theta) - g(u))/(alpha cos theta - u) dtheta.
long double reference_pressure(const Case& test, long double E, long double alpha, long double u, int nodes) {
  const auto g = [&](long double v) { return -E / 2 * test.y_prime(2 * std::atan(v)); };
  const long double gu = g(u);
  long double sum = 0;
  for (int k = 0; k < nodes; ++k) {
    const long double v = alpha * std::cos(pi_l * (k + 0.5L) / nodes);
    sum += (g(v) - gu) / (v - u);
  }
  return std::sqrt((alpha - u) * (alpha + u)) * sum / nodes;
}

}  // namespace

BOOST_AUTO_TEST_CASE(pressure_against_the_numerical_inversion) {
  const double b1 = 3.0, E = 2.0;
  for (const Case& test : cases()) {
    const Profile p = profile(test, b1, E);
    double worst = 0, worst_reference = 0;
    for (double fa : {0.02, 0.1, 0.3, 0.5, 0.7, 0.9}) {
      const double a = fa * b1;
      const long double alpha = std::tan(pi_l * a / (2 * b1));
      // cos(K x^) oscillates K alpha times faster in theta near v = 0 (dx^/dtheta = 2 alpha).
      const int nodes = (4 * test.order + 200) * static_cast<int>(std::ceil(std::max(1.0L, alpha)));
      double deviation = 0, reference_change = 0, scale = 0;
      for (double fx : {0.0, 0.1, 0.3, 0.6, 0.9, 0.99}) {
        const double x = fx * a;
        const long double u = std::tan(pi_l * x / (2 * b1));
        const long double coarse = pi_l / b1 * reference_pressure(test, E, alpha, u, nodes);
        const long double fine = pi_l / b1 * reference_pressure(test, E, alpha, u, 2 * nodes);
        reference_change = std::max(reference_change, static_cast<double>(std::fabs(fine - coarse)));
        deviation = std::max(deviation, static_cast<double>(std::fabs(p.pressure(a, x) - fine)));
        scale = std::max(scale, static_cast<double>(std::fabs(fine)));
      }
      BOOST_TEST(reference_change / scale <= 1e-15, test.name << ", a = " << a << ": the reference has not converged");
      BOOST_TEST(deviation / scale <= 1e-12, test.name << ", a = " << a << ": " << deviation / scale);
      worst = std::max(worst, deviation / scale);
      worst_reference = std::max(worst_reference, reference_change / scale);
    }
    BOOST_TEST_MESSAGE(test.name << " (order " << test.order << ") vs numerical inversion: max |dp| / max |p| = "
                                 << worst << " (reference converged to " << worst_reference << ")");
  }
}

BOOST_AUTO_TEST_CASE(load_slope_and_height) {
  const double b1 = 3.0, E = 2.0;
  for (const Case& test : cases()) {
    const Profile p = profile(test, b1, E);
    for (double fa : {0.05, 0.3, 0.6, 0.95}) {
      const double a = fa * b1;
      // x = a sin(phi) removes the square-root edge; the pressure of order K varies on a^/K.
      const auto integrand = [&](double phi) { return 2 * p.pressure(a, a * std::sin(phi)) * a * std::cos(phi); };
      // Composite Gauss-Legendre, 2K panels of 30 points.
      double quadrature = 0;
      const int panels = 2 * test.order;
      for (int i = 0; i < panels; ++i) {
        quadrature += boost::math::quadrature::gauss<double, 30>::integrate(integrand, M_PI / 2 * i / panels,
                                                                            M_PI / 2 * (i + 1) / panels);
      }
      BOOST_TEST(p.load(a) == quadrature, test.name << ", a = " << a << tt::tolerance(1e-11));
      // The load varies on a^/K: a fourth-order difference with steps of 1e-3 a/K.
      const double h = 1e-3 * a / test.order;
      const double difference =
          (8 * (p.load(a + h) - p.load(a - h)) - (p.load(a + 2 * h) - p.load(a - 2 * h))) / (12 * h);
      BOOST_TEST(p.load_slope(a) == difference, test.name << ", a = " << a << tt::tolerance(1e-8));
    }
    const wavecontact::ProfileEvaluator& e = p.evaluator();
    const std::vector<double>& q = p.parameter_values();
    double worst_height = 0, worst_slope = 0;
    for (double c : {1.0, 0.99995, 0.98, 0.5, 1e-4, -0.8, -0.9992, -1.0}) {
      const long double x = std::acos(static_cast<long double>(c));  // the c the evaluator sees
      worst_height = std::max(worst_height, static_cast<double>(std::fabs(e.height(q.data(), c) - test.y(x))));
      if (std::sin(x) > 1e-3) {  // dY/dc = y'(x) / (-sin x)
        const long double slope = test.y_prime(x) / -std::sin(x);
        const long double error = std::fabs(e.height_slope(q.data(), c) - slope) / (1 + std::fabs(slope));
        worst_slope = std::max(worst_slope, static_cast<double>(error));
      }
    }
    BOOST_TEST(worst_height <= 1e-14, test.name << ": height " << worst_height);
    BOOST_TEST(worst_slope <= 1e-12, test.name << ": dY/dCx " << worst_slope);
  }
}

// Full contact in closed form: the cosine sum's sum_k k A_k cos(k x) (harmonic_series.hpp) plus
// the rest's residues (derive/formulas/full_contact.hpp), against the profile's cosine coefficients
// (fourier_reference.hpp, 1024 points: exact for the cosine sums of order <= 256 and
// converged for c cos x/(2 - cos x)). Within 1e-12 of the largest |p_fc|.
BOOST_AUTO_TEST_CASE(full_contact_against_the_cosine_coefficients) {
  const double b1 = 3, E = 2, P = 0.5;
  for (const Case& test : cases()) {
    const Profile p = profile(test, b1, E);
    double worst = 0, scale = 0;
    for (double x : {0.0, 0.01, 0.4, 1.5, 2.9, 3.0}) {
      const double expected =
          P / (2 * b1) + E / 2 * M_PI / b1 * static_cast<double>(fourier_slope_sum(test.y, M_PI * x / b1, 1024));
      worst = std::max(worst, std::fabs(p.full_contact_pressure(P, x) - expected));
      scale = std::max(scale, std::fabs(expected - P / (2 * b1)));
    }
    BOOST_TEST_MESSAGE(test.name << ": full contact within " << worst / scale << " of max |p_fc|");
    BOOST_TEST(worst <= 1e-12 * scale, test.name << ": " << worst / scale);
  }
}
