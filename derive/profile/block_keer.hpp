// The Block-Keer change of variables (eq. 4): v = tan(x^/2) turns the periodic
// cot-kernel into the Hilbert kernel of eq. 5, and a profile that is rational in
// cos(k x^), sin(k x^) into a rational function of v.
#pragma once

#include <ginac/ginac.h>

namespace wavecontact::derive {

// cos(k x^) and sin(k x^) for v = tan(x^/2), by de Moivre:
// e^{i k x^} = (1 + i v)^{2k} / (1 + v^2)^k.
GiNaC::ex cos_multiple(long k, const GiNaC::ex& v);
GiNaC::ex sin_multiple(long k, const GiNaC::ex& v);

// e^{i x^} for v = tan(x^/2).
GiNaC::ex exp_i(const GiNaC::ex& v);

// The profile y(x^) (a GiNaC expression in sym::x(), rational in cos(k x^) and
// sin(k x^) for integer k) rewritten in v = tan(x^/2).
// Throws std::invalid_argument naming the offending subexpression otherwise.
GiNaC::ex in_half_angle_tangent(const GiNaC::ex& y);

// The even profile y(x^) as a rational function Y(c) of c = cos x^ (sym::Cx()), in lowest
// terms: cos(k x^) = T_k(c), sin(k x^) = sin x^ U_(k-1)(c), sin^2 x^ = 1 - c^2.
// Throws std::invalid_argument if y is not even or not rational in cos(k x^), sin(k x^).
GiNaC::ex in_cosine(const GiNaC::ex& y);

// Right-hand side of eq. 5: g(v) = -(E*/2) y'(x^(v)), in lowest terms.
GiNaC::ex hilbert_rhs(const GiNaC::ex& y);

}  // namespace wavecontact::derive
