// The roughness harmonic r(x) = H2 cos(n pi x/b1) (eq. 3) through the engine, and the
// exact, numerically stable form of its pressure for any even n (eqs. 15-21).
//
// Eq. 18 expands s(v) = sin(n x^)/n (eq. 17) as sum_j k_j v/(v^2+1)^j; the k_j grow like
// 4^n with alternating signs, so sums over them lose every digit in double precision by
// n ~ 32. The stable form comes from writing the bounded inversion (eq. 12) in x-space,
//   p^(x^) = (1/2pi) sqrt(cos x^ - cos a^) PV Int g(theta) / (sqrt(cos theta - cos a^) sin((theta - x^)/2)) dtheta,
// splitting sin(n theta) = sin(n x^) + 2 cos(n(theta+x^)/2) sin(n(theta-x^)/2), summing the
// Dirichlet kernel sin(n phi)/sin(phi) and applying Mehler-Dirichlet,
// P_k(cos a^) = (sqrt2/pi) Int_0^a^ cos((k+1/2) theta)/sqrt(cos theta - cos a^) dtheta:
//   p^_r(x^) = (E* H2 n / sqrt2) sqrt(cos x^ - cos a^) sum_{j=0}^{n-1} P_{n-1-j}(cos a^) cos((j+1/2) x^),
//   P_r = (pi/2) E* H2 n [P_{n-1}(cos a^) - P_n(cos a^)]   (docs/mathematics.md fact 6).
// Every term is bounded by 1: a sum of n bounded terms, stable in double precision. The
// derivation proves it equal to the engine's closed form for small n and checks it for
// every n (tests/roughness_test.cpp).
#pragma once

#include <vector>

#include <ginac/ginac.h>

#include "engine/radicals.hpp"

namespace wavecontact::derive {

// Throws std::invalid_argument naming the function unless n >= 2 is even.
void require_even(int n, const char* function);

// k_1..k_n of eq. 18, exactly, by the method of undetermined coefficients: the de Moivre
// numerator Im((1 + i v)^(2n)) = v P(v^2) re-expanded in powers of (1 + v^2). O(n^2)
// integer operations. Throws std::invalid_argument unless n >= 2 is even.
std::vector<GiNaC::numeric> expansion_coefficients(int n);

// The closed form k_j = (-1)^(n-j) C(n-1+j, n-j) 2^(2j-1) / n, from
// sum_j k_j z^j = sqrt(z) U_{2n-1}(sqrt(z)) / n (Chebyshev U; z = 1/(1+v^2)).
GiNaC::numeric chebyshev_coefficient(int n, int j);

// s(v) = sin(n x^)/n by de Moivre, as a rational function of v.
GiNaC::ex s_de_moivre(int n);

// Whether eq. 18's sum with the given k equals the de Moivre form exactly: both, times
// (1 + v^2)^n / v, are polynomials of degree n - 1 in v^2, compared in exact rational
// arithmetic at n points.
bool expansion_matches_de_moivre(int n, const std::vector<GiNaC::numeric>& k);

// Largest relative difference between the finite product of eq. 16/17 and the de Moivre
// form at n/2 + 1 points v in (0, 1], at `digits` decimal digits. Both are polynomials of
// degree n/2 - 1 in (2v/(1+v^2))^2 times the same factor, so agreement at n/2 + 1 points
// to working precision identifies them.
double product_form_deviation(int n, int digits);

// The roughness profile H2 cos(n x^) (eq. 3 with b1 -> pi).
GiNaC::ex roughness_profile(int n);

// The Legendre-Dirichlet form above, normalised (b1 = pi), in angle atoms:
// (E H2 n / 2) sqrt(D (1 + Cx)) sum_j P_{n-1-j}(Ca) V_j(Cx), V_j the Chebyshev polynomials of
// the third kind (cos((j+1/2)x) = cos(x/2) V_j(cos x)); and the load.
GiNaC::ex legendre_dirichlet_pressure(int n);
GiNaC::ex legendre_dirichlet_load(int n);

// The paper's eq. 19 for one term v/(v^2+1)^j: sqrt(alpha^2 - u^2)/((alpha^2+1)^(j/2) (u^2+1)^j),
// returned as I(s) with p = sqrt(alpha^2 - u^2) I (a RadicalSum over kappa(-1)).
RadicalSum eq19_term(int j, Radicals& radicals);

}  // namespace wavecontact::derive
