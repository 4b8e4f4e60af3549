// An independent reference for full contact (docs/mathematics.md fact 11): sum_k k y_k cos(k x) of an even
// 2 pi-periodic profile y from its cosine coefficients y_k = (2/N) sum_j y(x_j) cos(k x_j) at N
// equally spaced points (the trapezoid rule, geometrically convergent for an analytic y), in
// long double, up to k = N/2 - 1.
#pragma once

#include <cmath>
#include <vector>

#include <boost/math/constants/constants.hpp>

template <typename Profile>
long double fourier_slope_sum(const Profile& y, long double x, int N) {
  using boost::math::long_double_constants::pi;
  std::vector<long double> values(static_cast<std::size_t>(N));
  for (int j = 0; j < N; ++j) values[static_cast<std::size_t>(j)] = y(2 * pi * j / N);
  long double sum = 0;
  for (int k = 1; k < N / 2; ++k) {
    long double coefficient = 0;
    for (int j = 0; j < N; ++j) coefficient += values[static_cast<std::size_t>(j)] * std::cos(2 * pi * k * j / N);
    sum += k * (2 * coefficient / N) * std::cos(k * x);
  }
  return sum;
}
