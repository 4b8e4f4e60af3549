// The cost floor of the waviness array kernel: the exact pressure (generated/waviness_evaluators.hpp's
// formula) written plainly, compiled with -O3 -ffast-math once per array-kernel path
// (bench/CMakeLists.txt defines WAVECONTACT_PLAIN_ISA and the ISA's flags), so that glibc's
// vectorised cos (libmvec) and reciprocal multiplications serve it. Careless near the zone's
// edge (D = Cx - Ca cancels) and far from the 4 eps the library keeps: a baseline for speed
// only.
#include <cmath>

#include "plain_kernel.hpp"

#define WAVECONTACT_PLAIN_NAME_(isa) plain_waviness_pressure_##isa
#define WAVECONTACT_PLAIN_NAME(isa) WAVECONTACT_PLAIN_NAME_(isa)

namespace wavecontact::bench {

void WAVECONTACT_PLAIN_NAME(WAVECONTACT_PLAIN_ISA)(double E, double H1, double b1, double m, double a, const double* x,
                                                   double* p, std::size_t count) {
  const double pi = 3.14159265358979323846;
  const double Ca = std::cos(pi * a / b1), k = pi / (4 * b1) * E * H1 * (1 + m);
  for (std::size_t i = 0; i < count; ++i) {
    const double r = std::fabs(x[i]), Cx = std::cos(pi * r / b1), D = Cx - Ca;
    const double N = 2 + m * (3 + Ca) + m * m * (Cx + 2 * Ca - Ca * Cx);
    const double q = (1 + m * Ca) * (1 + m * Cx);
    const double value = k * (1 + Cx) * N * std::sqrt((1 + m * Ca) * D / ((1 + Cx) * (1 + m))) / (q * q);
    p[i] = r < a ? value : 0.0;
  }
}

}  // namespace wavecontact::bench
