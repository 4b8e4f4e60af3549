// The array kernel of the waviness pressure for a <= b1/2: the angle atoms by SLEEF's
// vectorised sincospi (3.5 ulp) and sinpi (0.506 ulp) four points at a time, then the generated closed
// form over a block, which the compiler vectorises. Built for AVX2 + FMA in its own
// translation unit (waviness_simd_avx2.cpp) and chosen at run time; other CPUs take the
// scalar path.
#pragma once

#include <cstddef>

#include "wavecontact/parameters.hpp"

namespace wavecontact::detail {

struct WavinessZone {
  double E, H1, b1, m, a, Ca, Sa;
};

// Whether this CPU runs the AVX2 kernel.
bool simd_pressure_available();

// p[i] for the points x[i], i < count (finite, any period); 0 outside the zone.
void simd_pressure(const WavinessZone& zone, Form form, const double* x, double* p,
                   std::size_t count);

}  // namespace wavecontact::detail
