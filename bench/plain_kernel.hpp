// The plain fast-math waviness kernel (plain_kernel.cpp), the speed baseline of the array API.
// Built for AVX2 + FMA: call only where the CPU has them.
#pragma once

#include <cstddef>

namespace wavecontact::bench {

void plain_waviness_pressure(double E, double H1, double b1, double m, double a, const double* x, double* p,
                             std::size_t count);

}  // namespace wavecontact::bench
