// The choice among the array kernels' ISA builds (pressure_simd.hpp) at run time, by
// array_kernel_isa(): AVX-512 where the CPU has it and the caller allows it, else AVX2 + FMA,
// else the scalar unit.

#include "kernels/pressure_simd.hpp"
#include "support/validate.hpp"
#include "wavecontact/isa.hpp"

namespace wavecontact::detail {

bool simd_roughness_available() { return array_kernel_isa() != Isa::scalar; }

// call, a function of the units, on array_kernel_isa()'s.
#define WAVECONTACT_ON_UNIT(call) \
  switch (array_kernel_isa()) {   \
    case Isa::avx512:             \
      return avx512::call;        \
    case Isa::avx2:               \
      return avx2::call;          \
    case Isa::scalar:             \
      break;                      \
  }                               \
  return scalar::call

void simd_pressure(const SimdWavinessZone& zone, Form form, const double* x, double* p, std::size_t count) {
  WAVECONTACT_ON_UNIT(simd_pressure(zone, form, x, p, count));
}

double simd_point_pressure(const SimdWavinessZone& zone, Form form, double x) {
  WAVECONTACT_ON_UNIT(simd_point_pressure(zone, form, x));
}

void simd_point_angles(double b1, double a, const double* x, std::size_t count, PointAngles* angles,
                       unsigned char* inside) {
  WAVECONTACT_ON_UNIT(simd_point_angles(b1, a, x, count, angles, inside));
}

bool simd_all_finite(const double* x, std::size_t count) { WAVECONTACT_ON_UNIT(simd_all_finite(x, count)); }

#undef WAVECONTACT_ON_UNIT

void simd_add_roughness_pressure(const RoughnessZone& zone, const double* x, double* p, std::size_t count) {
  if (array_kernel_isa() == Isa::avx512) return avx512::simd_add_roughness_pressure(zone, x, p, count);
  avx2::simd_add_roughness_pressure(zone, x, p, count);
}

bool all_finite(const double* x, std::size_t count) { return simd_all_finite(x, count); }

}  // namespace wavecontact::detail
