#include "wavecontact/isa.hpp"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace wavecontact {

namespace {

Isa requested_isa() {
  const char* value = std::getenv("WAVECONTACT_ISA");
  if (value == nullptr || *value == '\0') return Isa::avx512;  // the best there is
  for (Isa isa : {Isa::scalar, Isa::avx2, Isa::avx512}) {
    if (std::string(value) == isa_name(isa)) return isa;
  }
  throw std::domain_error(std::string("wavecontact::array_kernel_isa: WAVECONTACT_ISA = ") + value +
                          " is invalid (valid: scalar, avx2, avx512, or unset)");
}

}  // namespace

Isa cpu_isa() {
  static const Isa best = !(__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) ? Isa::scalar
                          : __builtin_cpu_supports("avx512f")                                ? Isa::avx512
                                                                                             : Isa::avx2;
  return best;
}

Isa array_kernel_isa() {
  static const Isa isa = std::min(requested_isa(), cpu_isa());
  return isa;
}

const char* isa_name(Isa isa) {
  switch (isa) {
    case Isa::scalar:
      return "scalar";
    case Isa::avx2:
      return "avx2";
    case Isa::avx512:
      return "avx512";
  }
  return "unknown";
}

}  // namespace wavecontact
