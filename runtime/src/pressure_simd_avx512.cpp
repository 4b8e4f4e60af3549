// Compiled with -mavx512f (runtime/CMakeLists.txt); called only where the CPU has it
// (avx512_available()). SLEEF only: no generated code is compiled with these flags.
#include <immintrin.h>
#include <sleef.h>

#include "pressure_simd.hpp"

namespace wavecontact::detail {

void sincospi_block_avx512(const double* t, double* s, double* c) {
  for (std::size_t k = 0; k < simd_block; k += 8) {
    const Sleef___m512d_2 sc = Sleef_sincospid8_u35avx512f(_mm512_load_pd(t + k));
    _mm512_store_pd(s + k, sc.x);
    _mm512_store_pd(c + k, sc.y);
  }
}

}  // namespace wavecontact::detail
