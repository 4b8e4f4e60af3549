#include "surface_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <boost/math/tools/minima.hpp>

#include "constants.hpp"
#include "zone.hpp"

namespace wavecontact::detail {

void SurfaceModel::height_differences(const double* x, std::size_t count, double x0, double* out) const {
  std::vector<double> ds(count), delta(count);
  for (std::size_t i = 0; i < count; ++i) ds[i] = cos_difference(x[i], x0), delta[i] = x[i] - x0;
  height_steps(x0, ds.data(), delta.data(), count, out, nullptr, nullptr);
}

void SurfaceModel::height_offsets(const double* x, const double* ds, std::size_t count, double x0, double* out,
                                  double* slopes) const {
  // sin(x - x0) = c0 sin x - c sin x0 = -ds (c0 (c + c0) / (sin x + sin x0) + sin x0), c = c0 + ds
  // (by sin x - sin x0 = (c0^2 - c^2) / (sin x + sin x0)): terms of one sign where c and c0 have
  // one sign; cos(x - x0) = c c0 + sin x sin x0.
  const double c0 = std::cos(x0), sin0 = std::sin(x0);
  std::vector<double> delta(count), sines(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double c = c0 + ds[i], sin_x = std::sin(x[i]);
    const double sine = -ds[i] * (c0 * (c + c0) / (sin_x + sin0) + sin0), cosine = c * c0 + sin_x * sin0;
    delta[i] = std::atan2(sine, cosine), sines[i] = sin_x;
  }
  height_steps(x0, ds, delta.data(), count, out, sines.data(), slopes);
}

void locate_top(SurfaceModel& surface) {
  const int samples = std::max(512, static_cast<int>(16 * pi / surface.resolution));
  double highest = -std::numeric_limits<double>::infinity(), lowest = -highest;
  int best = 0;
  for (int i = 0; i <= samples; ++i) {
    const double y = surface.height(pi * i / samples);
    if (y > highest) highest = y, best = i;
    lowest = std::min(lowest, y);
  }
  double top = pi * best / samples;
  if (best > 0 && best < samples) {
    const auto [x, y] = boost::math::tools::brent_find_minima([&](double x) { return -surface.height(x); },
                                                              pi * (best - 1) / samples, pi * (best + 1) / samples, 52);
    if (-y >= highest) top = x, highest = -y;
  }
  // -y'' by a central difference (y is even about 0 and pi).
  const double h = 1e-4 * surface.resolution;
  const auto y = [&](double x) { return surface.height(x < 0 ? -x : x > pi ? 2 * pi - x : x); };
  surface.top_angle = top;
  surface.top_curvature =
      std::max(-(y(top - h) - 2 * y(top) + y(top + h)) / (h * h), 1e-12 * std::max(highest - lowest, 1e-300));
  surface.height_range = highest - lowest;
}

}  // namespace wavecontact::detail
