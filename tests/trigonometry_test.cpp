// The array kernels' derived trigonometry (generated/bounded_trigonometry.hpp): sin(pi t)
// on |t| <= 1/4 within 1 ulp of the correctly rounded value, as the double evaluation runs
// it (fused multiply-adds), and within 2 ulp without them (sinpi_quarter_unfused, the scalar
// path's), against long double's sinl (11 more bits); odd and exact at 0.
#define BOOST_TEST_MODULE trigonometry
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>

#include "wavecontact/generated/bounded_trigonometry.hpp"

namespace {

const long double pi_l = 3.141592653589793238462643383279502884L;

// |computed - sin(pi t)| in ulps of sin(pi t) (the spacing of doubles at the true value).
double ulps(double computed, double t) {
  const long double exact = std::sin(pi_l * static_cast<long double>(t));
  const double rounded = static_cast<double>(exact);
  const double ulp = std::nextafter(std::fabs(rounded), std::numeric_limits<double>::infinity()) - std::fabs(rounded);
  return static_cast<double>(std::fabs(static_cast<long double>(computed) - exact)) / ulp;
}

template <typename Sine>
double worst_ulps(const Sine& sine, double bound) {
  double worst = 0;
  constexpr int samples = 400000;
  for (int i = 1; i <= samples; ++i) {
    // Uniform in t, and geometric towards 0 (where the relative accuracy is hardest).
    const double uniform = bound * i / samples;
    const double small = bound * std::ldexp(1.0 + (i % 1000) / 1000.0, -(i % 60) - 1);
    for (double t : {uniform, small, -uniform}) worst = std::max(worst, ulps(sine(t), t));
  }
  return worst;
}

}  // namespace

BOOST_AUTO_TEST_CASE(within_one_ulp_on_their_ranges) {
  const double quarter = worst_ulps([](double t) { return wavecontact::generated::sinpi_quarter(t); }, 0.25);
  BOOST_TEST_MESSAGE("sinpi_quarter: max " << quarter << " ulp");
  BOOST_TEST(quarter <= 1.0);
  const double unfused = worst_ulps([](double t) { return wavecontact::generated::sinpi_quarter_unfused(t); }, 0.25);
  BOOST_TEST_MESSAGE("sinpi_quarter_unfused: max " << unfused << " ulp");
  BOOST_TEST(unfused <= 2.0);
}

BOOST_AUTO_TEST_CASE(exact_where_sine_is) {
  using wavecontact::generated::sinpi_quarter;
  BOOST_TEST(sinpi_quarter(0.0) == 0.0);
  BOOST_TEST(ulps(sinpi_quarter(0.25), 0.25) <= 1.0);
  BOOST_TEST(sinpi_quarter(-0.2) == -sinpi_quarter(0.2));
  BOOST_TEST(ulps(sinpi_quarter(1e-300), 1e-300) <= 1.0);
  using wavecontact::generated::sinpi_quarter_unfused;
  BOOST_TEST(sinpi_quarter_unfused(0.0) == 0.0);
  BOOST_TEST(sinpi_quarter_unfused(-0.2) == -sinpi_quarter_unfused(0.2));
  BOOST_TEST(ulps(sinpi_quarter_unfused(1e-300), 1e-300) <= 1.0);
}
