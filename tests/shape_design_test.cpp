// Shape design (wavecontact/shape_design.hpp, `wavecontact optimize-shape`): the optimum of
// Brent's method against a brute-force scan of m, and max p / mean p against Westergaard.
#define BOOST_TEST_MODULE shape_design
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>

#include "wavecontact/shape_design.hpp"

namespace tt = boost::test_tools;

namespace {

struct Scan {
  double m, value;
};

// The smallest max p / mean p over `points` shapes spaced evenly in log(1 + m), m <= 100.
Scan brute_force(double ratio, int points) {
  Scan best{0, std::numeric_limits<double>::infinity()};
  for (int i = 0; i <= points; ++i) {
    const double m = std::expm1(std::log1p(100.0) * i / points);
    try {
      const double value = wavecontact::pressure_uniformity(m, ratio).max_over_mean;
      if (value < best.value) best = {m, value};
    } catch (const std::domain_error&) {  // infeasible shape
    }
  }
  return best;
}

}  // namespace

// m = 0: p = 2 p* cos(x/2) sqrt(sin^2(a/2) - sin^2(x/2)), pa/p* = sin^2(a/2), so
// max p / mean p = p(0) 2a / P = (2/pi) a^ / sin(a^/2).
BOOST_AUTO_TEST_CASE(sine_against_westergaard) {
  for (double ratio : {0.01, 0.2, 0.5, 0.9}) {
    const double s = std::sqrt(ratio), a_hat = 2 * std::asin(s);
    const auto u = wavecontact::pressure_uniformity(0, ratio);
    BOOST_TEST(u.max_over_mean == 2 / M_PI * a_hat / s, tt::tolerance(1e-12));
    BOOST_TEST(u.a_over_b1 == a_hat / M_PI, tt::tolerance(1e-12));
    BOOST_TEST(u.x_of_max_over_a < 1e-6);  // at the centre, to the precision of Brent
  }
}

// The optimum is at least as good as every shape of a fine scan, and next to the best one.
BOOST_AUTO_TEST_CASE(optimum_against_brute_force) {
  for (const auto& [ratio, points] : {std::pair{0.05, 1000}, {0.2, 1000}, {0.5, 1000}, {0.8, 40}}) {
    const Scan scan = brute_force(ratio, points);
    const auto best = wavecontact::most_uniform_shape(ratio);
    BOOST_TEST_MESSAGE("pa/p* = " << ratio << ": optimum m = " << best.m << ", max/mean = " << best.max_over_mean
                                  << "; scan of " << points + 1 << ": m = " << scan.m << ", " << scan.value);
    BOOST_TEST(best.max_over_mean <= scan.value + 1e-12);
    BOOST_TEST(scan.value - best.max_over_mean <= (points >= 1000 ? 1e-5 : 2e-2));
    const double spacing = std::log1p(100.0) / points;
    BOOST_TEST(std::fabs(std::log1p(best.m) - std::log1p(scan.m)) <= 2 * spacing);
    // The optimum is better than the sine and the flat punch end of the range.
    BOOST_TEST(best.max_over_mean < wavecontact::pressure_uniformity(0, ratio).max_over_mean);
    BOOST_TEST(best.max_over_mean < wavecontact::pressure_uniformity(100, ratio).max_over_mean);
  }
}

BOOST_AUTO_TEST_CASE(infeasible_loads_are_refused) {
  // m = 0.5 carries at most pa/p* = 0.90298 in one zone (then full contact).
  BOOST_CHECK_THROW(wavecontact::pressure_uniformity(0.5, 0.95), std::domain_error);
  BOOST_CHECK_THROW(wavecontact::most_uniform_shape(50.0, 10.0), std::domain_error);
  BOOST_CHECK_THROW(wavecontact::pressure_uniformity(-1, 0.5), std::domain_error);
}
