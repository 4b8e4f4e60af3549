// Which instruction set the array kernels run on (waviness.hpp, two_scale.hpp): the best the
// CPU has, or the one the environment variable WAVECONTACT_ISA asks for, capped at the CPU's
// (a path the CPU lacks cannot run). Read once, at the first array evaluation.
//   WAVECONTACT_ISA=scalar   the kernels' arithmetic one point at a time, without FMA (what CPUs
//                            without AVX2 + FMA take; the roughness there point by point)
//   WAVECONTACT_ISA=avx2     the AVX2 + FMA kernels, sincospi 4 wide
//   WAVECONTACT_ISA=avx512   the same with sincospi 8 wide (AVX-512F)
#pragma once

namespace wavecontact {

enum class Isa { scalar, avx2, avx512 };

// The path in use. Throws std::domain_error naming WAVECONTACT_ISA and its value if it is set
// to anything else than the three names above.
Isa array_kernel_isa();

// The best path this CPU has.
Isa cpu_isa();

const char* isa_name(Isa isa);

}  // namespace wavecontact
