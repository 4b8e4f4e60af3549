// The contact at wavelength ratios beyond 2048, up to max_roughness_n = 4096, where a wide zone's
// density needs more than 4096 Chebyshev nodes: the roughness H2 cos(n x^) is a polynomial of
// degree n in s = cos x^, and a zone spanning most of the period asks for nearly n + 1 terms.
// When a zone could hold at most 4096 nodes, its error estimate was its change from 2048,
// too few for such a degree: the contacts below, whose pressures were right within 1.3e-11,
// were reported with estimates of 2.8e-3 to 4.4e-3 (`wavecontact solve` exited with 4).
//
// On the sine (m = 0) with a roughness of slope H2 n = 0.003 the contact is one wide zone (at a
// slope of 0.03 the zone's edges have asperities of their own: three zones). Its
// pressure is the sine's closed form plus the roughness's Legendre-Dirichlet form
// (docs/derivation-roughness.md), summed here with Boost.Math's Legendre recurrence,
// independently of the solver and of generated/ (which holds no evaluator for these n):
//   p_r(x) = (pi/b1) (E* H2 n/sqrt2) sqrt(cos x^ - cos a^) sum_{j<n} P_{n-1-j}(cos a^) cos((j+1/2) x^),
//   P_r    = (pi/2) E* H2 n [P_{n-1}(cos a^) - P_n(cos a^)].
// The zone's end and pressure agree with the closed form, and the solver's estimate meets the
// tolerance.
#define BOOST_TEST_MODULE contact_large_n
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/legendre.hpp>

#include "wavecontact/contact.hpp"
#include "wavecontact/waviness.hpp"

using namespace wavecontact;

namespace {

using boost::math::double_constants::pi;
constexpr double b1 = 10, E = 1;

// P_0(c) .. P_n(c) by the three-term recurrence (stable for |c| <= 1).
std::vector<double> legendre_to(int n, double c) {
  std::vector<double> P{1.0, c};
  for (unsigned l = 1; static_cast<int>(l) < n; ++l) P.push_back(boost::math::legendre_next(l, c, P[l], P[l - 1]));
  return P;
}

// cos x^ at x.
double cos_angle(double x) { return std::cos(pi * x / b1); }

// The roughness's single zone of half-width a: its pressure at x (|x| < a) and its load.
struct RoughnessZone {
  double H2, a;
  int n;
  std::vector<double> P = legendre_to(n, cos_angle(a));

  double pressure(double x) const {
    const double q = pi * x / b1, Ca = cos_angle(a);
    double sum = 0;
    for (int j = 0; j < n; ++j) sum += P[static_cast<std::size_t>(n - 1 - j)] * std::cos((j + 0.5) * q);
    return pi / b1 * E * H2 * n / std::sqrt(2.0) * std::sqrt(std::max(0.0, std::cos(q) - Ca)) * sum;
  }
  double load() const {
    return pi / 2 * E * H2 * n * (P[static_cast<std::size_t>(n - 1)] - P[static_cast<std::size_t>(n)]);
  }
};

}  // namespace

BOOST_AUTO_TEST_CASE(a_wide_zone_beyond_n_2048_is_the_closed_form) {
  const WavinessParams sine{1.0, b1, 0.0, E};
  for (const int n : {3000, 4096}) {
    for (const double a : {0.5 * b1, 0.75 * b1}) {
      const double H2 = 0.003 / n, tolerance = 1e-8;
      const RoughnessZone roughness{H2, a, n};
      const double P = load(sine, a) + roughness.load();
      const Contact c = solve_contact(Surface(sine, {{H2, n}}), P, SolverOptions(tolerance));
      BOOST_TEST_REQUIRE(c.zones_per_period() == 1,
                         "n = " << n << ", a = " << a << ": " << c.zones_per_period() << " zones");
      BOOST_TEST(c.error_estimate() <= tolerance,
                 "n = " << n << ", a = " << a << ": error estimate " << c.error_estimate());
      const double end = std::fabs(c.zones()[0].x_end - a) / b1;
      BOOST_TEST(end < 1e-10, "n = " << n << ", a = " << a << ": the zone ends " << c.zones()[0].x_end
                                     << ", the closed form's " << a);
      // Up to a (1 - 1e-4): nearer the end, p ~ sqrt(a - x) turns the end's rounding into larger
      // differences of p (the largest, 8e-11 at n = 4096, is at that last point).
      double worst = 0, scale = 0, at = 0;
      for (int i = 0; i <= 64; ++i) {
        const double x = a * (i < 60 ? i / 60.0 : 1 - std::pow(10.0, -(i - 60)));
        const double expected = pressure(sine, a, x) + roughness.pressure(x);
        if (std::fabs(c.pressure(x) - expected) > worst) worst = std::fabs(c.pressure(x) - expected), at = x;
        scale = std::max(scale, expected);
      }
      BOOST_TEST(worst / scale < 1e-10,
                 "n = " << n << ", a = " << a << ": pressure off by " << worst / scale << " of its largest");
      BOOST_TEST_MESSAGE("n = " << n << ", a = " << a << ": " << c.nodes_per_zone() << " nodes, end off by " << end
                                << " of b1, pressure by " << worst / scale << " at x = " << at << ", estimate "
                                << c.error_estimate());
    }
  }
}
