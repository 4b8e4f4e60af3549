// The choice among the array kernels' ISA builds (pressure_simd.hpp) at run time, by
// array_kernel_isa(): AVX-512 where the CPU has it and the caller allows it, else AVX2.
#include <algorithm>
#include <cmath>

#include "kernels/pressure_simd.hpp"
#include "support/validate.hpp"
#include "wavecontact/isa.hpp"

namespace wavecontact::detail {

bool simd_pressure_available() { return array_kernel_isa() != Isa::scalar; }

void simd_pressure(const SimdWavinessZone& zone, Form form, const double* x, double* p, std::size_t count) {
  if (array_kernel_isa() == Isa::avx512) return avx512::simd_pressure(zone, form, x, p, count);
  avx2::simd_pressure(zone, form, x, p, count);
}

double simd_point_pressure(const SimdWavinessZone& zone, Form form, double x) {
  if (array_kernel_isa() == Isa::avx512) return avx512::simd_point_pressure(zone, form, x);
  return avx2::simd_point_pressure(zone, form, x);
}

void simd_point_angles(double b1, double a, const double* x, std::size_t count, PointAngles* angles,
                       unsigned char* inside) {
  if (array_kernel_isa() == Isa::avx512) return avx512::simd_point_angles(b1, a, x, count, angles, inside);
  avx2::simd_point_angles(b1, a, x, count, angles, inside);
}

void simd_add_roughness_pressure(const RoughnessZone& zone, const double* x, double* p, std::size_t count) {
  if (array_kernel_isa() == Isa::avx512) return avx512::simd_add_roughness_pressure(zone, x, p, count);
  avx2::simd_add_roughness_pressure(zone, x, p, count);
}

bool simd_all_finite(const double* x, std::size_t count) {
  if (array_kernel_isa() == Isa::avx512) return avx512::simd_all_finite(x, count);
  return avx2::simd_all_finite(x, count);
}

bool all_finite(const double* x, std::size_t count) {
  if (simd_pressure_available()) return simd_all_finite(x, count);
  return std::all_of(x, x + count, [](double v) { return std::isfinite(v); });
}

}  // namespace wavecontact::detail
