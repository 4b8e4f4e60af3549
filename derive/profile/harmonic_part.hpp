// The harmonic part of a profile, through the Legendre-Dirichlet form.
//
// An even profile is a rational function of c = cos x^: y = Y(c). Its polynomial part is a
// cosine sum, so
//   y(x^) = sum_{k=0}^{K} A_k cos(k x^) + R(cos x^),   R proper (or constant),
// and the two parts are inverted apart. The harmonic part is the whole of the pole of g(v)
// at v^2 = -1 (c = infinity), whose order K makes the partial fractions of the engine
// (hilbert.hpp) cost like a high power of K. Each harmonic has the Legendre-Dirichlet form
// of the roughness (roughness.hpp), summed over k:
//   p^(x^) = (E*/2) sqrt(D (1 + Cx)) sum_{j<K} B_j(Ca) V_j(Cx),
//   B_j = sum_{k>j} k A_k P_{k-1-j}(Ca),                     (normalised: b1 = pi)
//   P   = (pi/2) E* sum_k k A_k [P_{k-1}(Ca) - P_k(Ca)],
//   dP/da^ = sin(a^) (pi/2) E* sum_k k A_k [P'_k(Ca) - P'_{k-1}(Ca)],
// V_j the Chebyshev polynomials of the third kind, P_k Legendre's: sums of terms bounded by
// max |k A_k|, stable in double precision for any K (runtime harmonic_series.hpp sums them).
// The proper part R has the poles of g off v^2 = -1 and goes through the engine.
#pragma once

#include <vector>

#include <ginac/ginac.h>

namespace wavecontact::derive {

struct HarmonicSplit {
  // A_0..A_K of the cosine sum, rational in the parameters; empty if there is none.
  std::vector<GiNaC::ex> cosine;
  // R(c), c = sym::Cx(): the rest of Y, proper or constant, zero for a cosine sum.
  GiNaC::ex rational;
};

// Splits Y(c) (rational in sym::Cx()) into its cosine sum and the rest. The split is made
// when Y's denominator has a leading coefficient in c that is a number, or does not depend
// on c; when it depends on the parameters (the wave curve's m cos x + 1), the polynomial
// part would carry its inverse, singular where the pole passes through c = infinity
// (m = 0), so Y is kept whole: cosine empty, rational = Y.
HarmonicSplit split_harmonic_part(const GiNaC::ex& Y);

// The coefficients of a polynomial in c in the Chebyshev basis T_k(c), k = 0..degree.
std::vector<GiNaC::ex> chebyshev_t_coefficients(const GiNaC::ex& polynomial, const GiNaC::ex& c);

// Legendre polynomial P_k(y), by the three-term recurrence.
GiNaC::ex legendre_polynomial(int k, const GiNaC::ex& y);

// The forms above as expressions in the angle atoms (normalised, b1 = pi), for proofs and
// tests: the pressure, the load and dP/dSa - dP/dCa (dP/da^ = sin(a^) times it).
GiNaC::ex harmonic_pressure(const std::vector<GiNaC::ex>& cosine);
GiNaC::ex harmonic_load(const std::vector<GiNaC::ex>& cosine);
GiNaC::ex harmonic_load_slope_factor(const std::vector<GiNaC::ex>& cosine);

}  // namespace wavecontact::derive
