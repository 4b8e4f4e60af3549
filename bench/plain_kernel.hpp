// The plain fast-math waviness kernel (plain_kernel.cpp), the speed limit of the array API,
// built once per array-kernel path (bench/CMakeLists.txt): compare each path with its own.
#pragma once

#include <cstddef>

#include "wavecontact/isa.hpp"

namespace wavecontact::bench {

using PlainKernel = void (*)(double E, double H1, double b1, double m, double a, const double* x, double* p,
                             std::size_t count);

// scalar: -O3 -ffast-math, not vectorised; avx2: the same with AVX2 + FMA and libmvec's cos;
// avx512: with AVX-512F. Call a build only where the CPU has its ISA.
void plain_waviness_pressure_scalar(double E, double H1, double b1, double m, double a, const double* x, double* p,
                                    std::size_t count);
void plain_waviness_pressure_avx2(double E, double H1, double b1, double m, double a, const double* x, double* p,
                                  std::size_t count);
void plain_waviness_pressure_avx512(double E, double H1, double b1, double m, double a, const double* x, double* p,
                                    std::size_t count);

inline PlainKernel plain_waviness_pressure(Isa isa) {
  return isa == Isa::avx512 ? plain_waviness_pressure_avx512
         : isa == Isa::avx2 ? plain_waviness_pressure_avx2
                            : plain_waviness_pressure_scalar;
}

}  // namespace wavecontact::bench
