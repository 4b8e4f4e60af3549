// Compiled with -mavx2 -mfma -O3 -fno-math-errno (runtime/CMakeLists.txt); called only where
// the CPU has both (array_kernel_isa()).
#include "pressure_simd_kernels.hpp"

namespace wavecontact::detail {

void simd_pressure_avx2(const WavinessZone& zone, Form form, const double* x, double* p,
                        std::size_t count) {
  pressure_kernel(zone, form, x, p, count);
}

void simd_add_roughness_pressure_avx2(const RoughnessZone& zone, const double* x, double* p,
                                      std::size_t count) {
  add_roughness_kernel(zone, x, p, count);
}

}  // namespace wavecontact::detail
