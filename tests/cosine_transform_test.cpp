// The contact solver's cosine transforms (runtime/src/contact/cosine_transform.*), white-box:
// FFTW's DCT-I, DCT-II and DCT-III against their defining sums in long double, the error in eps of
// the sum of the terms' magnitudes (below 0.7 at every size here, 2026-11-29).
#define BOOST_TEST_MODULE cosine_transform
#include <boost/math/constants/constants.hpp>
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <vector>

#include "contact/cosine_transform.hpp"

using wavecontact::detail::CosineTransform;
using wavecontact::detail::planned_transform;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

std::vector<double> random_values(std::size_t n, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> value(-1, 1);
  std::vector<double> x(n);
  for (double& v : x) v = value(generator);
  return x;
}

// The largest error over k in eps of sum_j |term| of the transform of this kind applied to
// random values (seeded), the terms cos(theta(j, k)) weighted.
template <class Theta, class Weight>
double error_in_eps(CosineTransform::Kind kind, std::size_t points, unsigned seed, Theta theta, Weight weight,
                    std::size_t k_step = 1) {
  using boost::math::long_double_constants::pi;
  const std::vector<double> x = random_values(points, seed);
  CosineTransform& t = planned_transform(points, kind);
  t.data() = x;
  t.apply();
  const std::vector<double>& y = t.data();
  double worst = 0;
  for (std::size_t k = 0; k < y.size(); k += k_step) {
    long double sum = 0, size = 0;
    for (std::size_t j = 0; j < x.size(); ++j) {
      const long double term = weight(j) * x[j] * std::cos(pi * theta(j, k));
      sum += term, size += std::fabs(term);
    }
    worst = std::max(worst, static_cast<double>(std::fabs(y[k] - sum) / (eps * size)));
  }
  return worst;
}

}  // namespace

// y_k = x_0 + (-1)^k x_N + 2 sum_{j=1}^{N-1} x_j cos(pi j k / N), k = 0 .. N; at the grid
// seed's largest sizes (n = 4096: 65537 points), every 509th k.
BOOST_AUTO_TEST_CASE(dct1_is_its_sum) {
  for (std::size_t points : {2, 3, 17, 129, 257, 513, 1025, 8193, 65537}) {
    const std::size_t N = points - 1;
    const double error = error_in_eps(
        CosineTransform::Kind::dct1, points, static_cast<unsigned>(points),
        [N](std::size_t j, std::size_t k) { return static_cast<long double>(j * k % (2 * N)) / N; },
        [N](std::size_t j) { return j == 0 || j == N ? 1.0L : 2.0L; }, points > 1025 ? 509 : 1);
    BOOST_TEST_MESSAGE("DCT-I of " << points << " points: " << error << " eps");
    BOOST_TEST(error < 4, "DCT-I of " << points << " points: " << error << " eps of the terms");
  }
}

// y_k = 2 sum_j x_j cos(pi k (j + 1/2) / N), k = 0 .. N - 1.
BOOST_AUTO_TEST_CASE(dct2_is_its_sum) {
  for (std::size_t points : {129, 160, 200, 256}) {
    const double error = error_in_eps(
        CosineTransform::Kind::dct2, points, static_cast<unsigned>(points),
        [points](std::size_t j, std::size_t k) { return static_cast<long double>(k * (2 * j + 1)) / (2 * points); },
        [](std::size_t) { return 2.0L; });
    BOOST_TEST_MESSAGE("DCT-II of " << points << " points: " << error << " eps");
    BOOST_TEST(error < 4, "DCT-II of " << points << " points: " << error << " eps of the terms");
  }
}

// y_k = x_0 + 2 sum_{j=1}^{N-1} x_j cos(pi j (k + 1/2) / N), k = 0 .. N - 1.
BOOST_AUTO_TEST_CASE(dct3_is_its_sum) {
  for (std::size_t points : {129, 160, 200, 1024}) {
    const double error = error_in_eps(
        CosineTransform::Kind::dct3, points, static_cast<unsigned>(points) + 1,
        [points](std::size_t j, std::size_t k) { return static_cast<long double>(j * (2 * k + 1)) / (2 * points); },
        [](std::size_t j) { return j == 0 ? 1.0L : 2.0L; });
    BOOST_TEST_MESSAGE("DCT-III of " << points << " points: " << error << " eps");
    BOOST_TEST(error < 4, "DCT-III of " << points << " points: " << error << " eps of the terms");
  }
}
