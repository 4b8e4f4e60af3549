// The roughness harmonic's evaluators for one n as straight-line programs
// (formulas/roughness.hpp derives the forms they evaluate).
#pragma once

#include "emit/cxx_emitter.hpp"

namespace wavecontact::derive {

// The emitted evaluators for one n, as straight-line programs over the angle atoms:
//   roughness_n<N>_pressure(E, H2, b1, Ca, Sa, Cx, Sx, D): p_r(x) in physical units, the
//     Legendre values by their three-term recurrence and the sum over V_j(Cx) by Clenshaw's
//     recurrence in Reinsch's form (d_j = c_j - 2 Sx b_{j+1} + d_{j+1}, b_j = d_j + b_{j+1}),
//     which does not amplify rounding near Cx = 1;
//   roughness_n<N>_load(E, H2, Ca, Sa): (pi/2) E H2 n [P_{n-1} - P_n](Ca) through
//     D_{k+1} = (k D_k + (2k+1) Sa P_k)/(k+1), D_1 = Sa, free of cancellation near Ca = 1.
//   roughness_n<N>_legendre(Ca, out): out[k] = P_k(Ca), k < n, the same recurrence, for
//     evaluators that sum the series over many points of one zone (the runtime's array path).
EmittedFunction roughness_pressure_program(int n);
EmittedFunction roughness_load_program(int n);
EmittedFunction roughness_legendre_program(int n);

// Eq. 15, full contact of the harmonic: p_rf = p*_r (cos(n x^) + 1), p*_r = pi E* H2 n/(2 b1),
// at the onset of full contact (mean pressure p*_r). It is the a -> b1 limit of the exact
// partial-contact pressure, p*_r (cos(n x^) - 1), plus the uniform pressure 2 p*_r that full
// contact admits (the periodic Hilbert transform of a constant vanishes); the tests check
// that limit on the emitted per-n evaluators.
EmittedFunction roughness_full_contact_program();

}  // namespace wavecontact::derive
