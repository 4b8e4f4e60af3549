// The fixed rule for integrands with logarithmic singularities at or next to both ends
// (runtime/src/contact/log_end_quadrature.hpp), which the kink corrections' potentials and
// moments are computed by: against closed forms, the error in units of eps times Int |f|.
#define BOOST_TEST_MODULE log_end_quadrature
#include <boost/math/constants/constants.hpp>
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <string>

#include "contact/log_end_quadrature.hpp"

using boost::math::double_constants::pi;
using wavecontact::detail::log_end_integral;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

std::string format(double x) {
  std::ostringstream text;
  text << x;
  return text.str();
}

// The error of the rule on [a, b] in units of eps Int |f| (Int |f| by the rule itself).
double error_in_eps(const std::function<double(double)>& f, double a, double b, double expected) {
  const double got = log_end_integral(f, a, b);
  const double size = log_end_integral([&](double t) { return std::fabs(f(t)); }, a, b);
  return std::fabs(got - expected) / (eps * size);
}

// f last, so that its lambda closes the call.
void check(const std::string& what, double a, double b, double expected, double bound,
           const std::function<double(double)>& f) {
  const double error = error_in_eps(f, a, b, expected);
  BOOST_TEST_MESSAGE(what << ": " << error << " eps");
  BOOST_TEST(error < bound, what << ": got " << log_end_integral(f, a, b) << ", expected " << expected << ", " << error
                                 << " eps of Int |f|");
}

}  // namespace

BOOST_AUTO_TEST_CASE(logarithms_at_the_ends) {
  check("Int_0^1 log t", 0, 1, -1, 8, [](double t) { return std::log(t); });
  check("Int_0^1 log^2 t", 0, 1, 2, 8, [](double t) { return std::log(t) * std::log(t); });
  check("Int_0^1 log t log(1 - t)", 0, 1, 2 - pi * pi / 6, 8,
        [](double t) { return t < 1 ? std::log(t) * std::log1p(-t) : 0.0; });
  // Int_0^1 t^k log t = -1/(k + 1)^2 and Int_0^1 t^k log(1 - t) = -H_(k+1)/(k + 1): a smooth
  // factor of growing degree at either end, as a window's density (degree 48) times a
  // logarithm. Beyond degree 24 the second errs by up to 19.9 eps.
  double harmonic = 0;
  for (int k = 0; k <= 48; ++k) {
    harmonic += 1.0 / (k + 1);
    const double bound = k <= 24 ? 16 : 24;
    check("Int_0^1 t^" + std::to_string(k) + " log t", 0, 1, -1.0 / ((k + 1) * (k + 1)), bound,
          [k](double t) { return std::pow(t, k) * std::log(t); });
    check("Int_0^1 t^" + std::to_string(k) + " log(1 - t)", 0, 1, -harmonic / (k + 1), bound,
          [k](double t) { return t < 1 ? std::pow(t, k) * std::log1p(-t) : 0.0; });
  }
}

// A singularity a distance d beyond an end (the kink next to a stretch that ends at the point
// where the potential is taken): Int_0^1 log(t + d) = (1 + d) log(1 + d) - d log d - 1, at
// every scale of d from the stretch's own down to below rounding. The windows take d down to
// about 3e-7 of the stretch (the extrema of a piece next to the kink, 257 nodes on r/64 of
// 2 r); at 1e-8 to 1e-13 the rule errs by up to 105 eps.
BOOST_AUTO_TEST_CASE(logarithms_next_to_the_ends) {
  for (int e = 0; e <= 17; ++e) {
    const double d = std::pow(10.0, -e), expected = (1 + d) * std::log1p(d) - d * std::log(d) - 1;
    const double bound = e <= 7 || e >= 15 ? 16 : 128;
    check("Int_0^1 log(t + " + format(d) + ")", 0, 1, expected, bound, [d](double t) { return std::log(t + d); });
    check("Int_0^1 log(1 + " + format(d) + " - t)", 0, 1, expected, bound,
          [d](double t) { return std::log((1 - t) + d); });
  }
}

// The rule is the same on every stretch: Int_a^(a + L) log(t - a) = L (log L - 1), from either
// end, down to stretches of 1e-12 next to a = 0. Next to another a, f sees t, whose distance
// from a carries a's rounding: the points nearest a lose their digits, as they would with any
// rule that reaches within a's rounding of it (tanh-sinh too), and on L = 1e-3 next to a = 0.3
// the error grows to about 700 eps (a window's kink at s0 != 0: a user profile's).
BOOST_AUTO_TEST_CASE(any_stretch) {
  for (double length : {2.0, 1e-3, 1e-8, 1e-12}) {
    const double expected = length * (std::log(length) - 1);
    check("Int_0^L log t, L = " + format(length), 0, length, expected, 16, [](double t) { return std::log(t); });
    check("Int_-L^0 log(-t), L = " + format(length), -length, 0, expected, 16, [](double t) { return std::log(-t); });
  }
  for (double a : {-1.0, 0.3}) {
    for (double length : {2.0, 1e-3}) {
      check("Int log(t - a), a = " + format(a) + ", L = " + format(length), a, a + length,
            length * (std::log(length) - 1), length > 1 ? 16 : 1024,
            [a](double t) { return t > a ? std::log(t - a) : 0.0; });
    }
  }
  BOOST_TEST(log_end_integral([](double) { return 1.0; }, 1, 1) == 0);
  BOOST_TEST(log_end_integral([](double) { return 1.0; }, 1, 0) == 0);
}
