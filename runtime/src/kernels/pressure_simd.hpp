// The array kernels of the pressure for a <= b1/2: the angle atoms from the generated
// bounded sines (generated/bounded_trigonometry.hpp), then, over a block of points, either
// the generated waviness closed form or the roughness series with the zone's generated
// Legendre coefficients, all in loops the compiler vectorises (pressure_simd_kernels.hpp); and
// the check that an array's points are finite.
// Built once per ISA in its own translation unit, all from pressure_simd_unit.inc
// (pressure_simd_avx2.cpp: AVX2 + FMA; pressure_simd_avx512.cpp: AVX-512F;
// pressure_simd_scalar.cpp: neither vectors nor FMA, the waviness's kernels only) and chosen at
// run time (array_kernel_isa()). Without AVX2 the roughness takes its scalar path.
#pragma once

#include <cstddef>

#include "wavecontact/angles.hpp"
#include "wavecontact/parameters.hpp"

namespace wavecontact::detail {

// One zone of the wave curve, a <= b1/2; sin_a = sin(pi a/b1) = sqrt(Sa (1 + Ca)).
struct SimdWavinessZone {
  double E, H1, b1, m, a, Ca, Sa, sin_a;
};

// One zone of the roughness harmonic, n = count of legendre:
//   p_r = scale sqrt(D (1 + Cx)) sum_{j<n} P_{n-1-j}(Ca) V_j(Cx), scale = pi E* H2 n/(2 b1),
// legendre[k] = P_k(Ca) from the generated roughness_n<N>_legendre.
struct RoughnessZone {
  double b1, a, Ca, Sa, scale;
  const double* legendre;
  int n;
};

// Whether this CPU runs the roughness's vector kernel (array_kernel_isa() is not scalar).
bool simd_roughness_available();

// Points per pass of the kernels; a multiple of 8.
inline constexpr std::size_t simd_block = 256;

// p[i] for the points x[i], i < count (finite, any period); 0 outside the zone. On the
// ISA of array_kernel_isa().
void simd_pressure(const SimdWavinessZone& zone, Form form, const double* x, double* p, std::size_t count);

// p at one point x, |x| <= b1, by the same arithmetic; as above.
double simd_point_pressure(const SimdWavinessZone& zone, Form form, double x);

// p[i] += p_r(x[i]) for the points x[i], i < count (finite, any period); call only if
// simd_roughness_available().
void simd_add_roughness_pressure(const RoughnessZone& zone, const double* x, double* p, std::size_t count);

// The angle atoms of the points x[i], i < count (finite, any period), for a zone 0 < a <= b1,
// from the bounded sines as the kernels take them: angles[i] where |x[i]| reduced to the period
// is < a (inside[i] = 1), inside[i] = 0 elsewhere. As above.
void simd_point_angles(double b1, double a, const double* x, std::size_t count, PointAngles* angles,
                       unsigned char* inside);

// Whether x[i], i < count, are all finite. As above.
bool simd_all_finite(const double* x, std::size_t count);

// The same per ISA.
namespace avx2 {
#include "kernels/pressure_simd_entry_points.inc"
void simd_add_roughness_pressure(const RoughnessZone& zone, const double* x, double* p, std::size_t count);
}  // namespace avx2
namespace avx512 {
#include "kernels/pressure_simd_entry_points.inc"
void simd_add_roughness_pressure(const RoughnessZone& zone, const double* x, double* p, std::size_t count);
}  // namespace avx512
namespace scalar {
#include "kernels/pressure_simd_entry_points.inc"
}  // namespace scalar

}  // namespace wavecontact::detail
