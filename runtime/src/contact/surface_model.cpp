#include "surface_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/math/tools/minima.hpp>

#include "constants.hpp"

namespace wavecontact::detail {

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
