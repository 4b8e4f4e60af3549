// Compiled with -mavx512f -mavx2 -mfma -O3 -fno-math-errno (runtime/CMakeLists.txt); called
// only where the CPU has AVX-512F (array_kernel_isa()). The same kernels as the AVX2 unit,
// 8 points a vector.
#include "pressure_simd_kernels.hpp"

namespace wavecontact::detail {

void simd_pressure_avx512(const WavinessZone& zone, Form form, const double* x, double* p,
                          std::size_t count) {
  pressure_kernel(zone, form, x, p, count);
}

void simd_add_roughness_pressure_avx512(const RoughnessZone& zone, const double* x, double* p,
                                        std::size_t count) {
  add_roughness_kernel(zone, x, p, count);
}

void simd_point_angles_avx512(double b1, double a, const double* x, std::size_t count, PointAngles* angles,
                           unsigned char* inside) {
  point_angles_kernel(b1, a, x, count, angles, inside);
}

bool simd_all_finite_avx512(const double* x, std::size_t count) { return all_finite_kernel(x, count); }

}  // namespace wavecontact::detail
