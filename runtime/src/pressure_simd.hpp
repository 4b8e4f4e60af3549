// The array kernels of the pressure for a <= b1/2: the angle atoms by SLEEF's vectorised
// sincospi (3.5 ulp, 4 or 8 points at a time), then, over a block of
// points, either the generated waviness closed form (which the compiler vectorises) or the
// roughness series with the zone's generated Legendre coefficients. Built for AVX2 + FMA in
// their own translation unit (pressure_simd_avx2.cpp) and chosen at run time; other CPUs
// take the scalar paths.
#pragma once

#include <cstddef>

#include "wavecontact/parameters.hpp"

namespace wavecontact::detail {

struct WavinessZone {
  double E, H1, b1, m, a, Ca, Sa;
};

// One zone of the roughness harmonic, n = count of legendre:
//   p_r = scale sqrt(D (1 + Cx)) sum_{j<n} P_{n-1-j}(Ca) V_j(Cx), scale = pi E* H2 n/(2 b1),
// legendre[k] = P_k(Ca) from the generated roughness_n<N>_legendre.
struct RoughnessZone {
  double b1, a, scale;
  const double* legendre;
  int n;
};

// Whether this CPU runs the AVX2 kernels, and AVX-512 (for their sincospi).
bool simd_pressure_available();
bool avx512_available();

// Points per pass of the kernels; a multiple of 8.
inline constexpr std::size_t simd_block = 256;

// sin(pi t[k]) and cos(pi t[k]) for k < simd_block (SLEEF, 3.5 ulp), 8 at a time; t, s
// and c aligned to 64 bytes. Built with -mavx512f: call only if avx512_available().
void sincospi_block_avx512(const double* t, double* s, double* c);

// p[i] for the points x[i], i < count (finite, any period); 0 outside the zone.
void simd_pressure(const WavinessZone& zone, Form form, const double* x, double* p,
                   std::size_t count);

// p[i] += p_r(x[i]) for the points x[i], i < count (finite, any period).
void simd_add_roughness_pressure(const RoughnessZone& zone, const double* x, double* p,
                                 std::size_t count);

}  // namespace wavecontact::detail
