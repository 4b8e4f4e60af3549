// The wave curve and points the waviness benchmarks share (wavecontact_bench.cpp,
// latency_bench.cpp, and bench/python_pressure.py's same numbers): m = 2, a = 0.4 b1.
#pragma once

#include <Eigen/Core>

#include "wavecontact/parameters.hpp"

namespace wavecontact::bench {

inline const WavinessParams waviness{1.0, 10.0, 2.0, 1.0};
inline constexpr double half_width = 4.0;         // a/b1 = 0.4
inline constexpr double half_width_beyond = 7.5;  // a/b1 = 0.75: across the kink at b1/2

// count points evenly over 0.999 of the zone |x| < a.
inline Eigen::ArrayXd zone_points(Eigen::Index count, double a) {
  return Eigen::ArrayXd::LinSpaced(count, -0.999 * a, 0.999 * a);
}

}  // namespace wavecontact::bench
