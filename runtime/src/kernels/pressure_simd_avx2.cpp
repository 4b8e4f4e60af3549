// The array kernels for AVX2 + FMA (flags in runtime/CMakeLists.txt), 4 points a vector;
// called only where the CPU has both (array_kernel_isa()).
#include "kernels/pressure_simd_kernels.hpp"

namespace wavecontact::detail::avx2 {
#include "kernels/pressure_simd_unit.inc"
}  // namespace wavecontact::detail::avx2
