// The array kernels for AVX-512F (flags in runtime/CMakeLists.txt), 8 points a vector;
// called only where the CPU has it (array_kernel_isa()).
#include "kernels/pressure_simd_kernels.hpp"

namespace wavecontact::detail::avx512 {
#include "kernels/pressure_simd_unit.inc"
}  // namespace wavecontact::detail::avx512
