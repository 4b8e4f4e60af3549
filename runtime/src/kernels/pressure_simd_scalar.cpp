// The array kernels for CPUs without AVX2 + FMA (flags in runtime/CMakeLists.txt: no vector
// unit, no FMA): the waviness's arithmetic one point at a time, each product and sum rounded
// apart (pressure_simd_kernels.hpp's multiply_add and bounded_sinpi).
#include "kernels/pressure_simd_kernels.hpp"

namespace wavecontact::detail::scalar {
#include "kernels/pressure_simd_unit.inc"
}  // namespace wavecontact::detail::scalar
