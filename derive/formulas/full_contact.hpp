// Full contact (a = b1, docs/mathematics.md fact 11) in closed form: p = pa + p_fc, where for
// y = sum_k y_k cos(k x^)
//   p_fc(x) = (E*/2)(pi/b1) sum_k k y_k cos(k x^) = (E*/2)(pi/b1) d(y~)/dx^,
// y~ the conjugate function of y. Under v = tan(x^/2) (eq. 4) the conjugate function is the
// Hilbert transform on the line, y~(v) = H[Y](v) = (1/pi) PV Int Y(u^2)/(v - u) du for
// y(x^) = Y(t), t = v^2, and for a pole 1/(t - tau), tau < 0, H = v/(sqrt(-tau)(v^2 - tau)):
// so H[Y] is the sum over Y's poles of the residues at t = tau of Y(t) v/(sqrt(-t)(v^2 - t)),
// taken from the Taylor series at tau (with 1/sqrt(-t) = (1/sqrt(-tau)) (1 + h/tau)^(-1/2),
// h = t - tau). A cosine sum's part is the sum itself (harmonic_series.hpp).
//
// A profile built with abs() (branches.hpp) is Y_top on t < beta^2 and Y_flank beyond. Its
// p_fc is the conjugate of the slope: with y' dx^ = 2u Y'(u^2) du and cot((x^ - xi)/2) =
// (1 + u v)/(v - u), the odd part integrating to 0,
//   p_fc = (E*/b1) (1 + t) Int_0^inf F(u^2)/(t - u^2) du,  F = t Y'(t)  (F_top, F_flank by piece),
// no derivative of a transcendental term needed. Each branch's F is N(t)/(a + b t)^L, N of degree
// <= L, its one pole factor kept whole (no coefficient singular as b -> 0, a pole passing through
// infinity as the top's of eq. 2 does at m = 1), so every integral is a sum of monomial atoms
// I_{j,L} (J_{j,L} with the Cauchy factor 1/(t - u^2) kept) of sub_interval.hpp over
// [0, beta] (u = beta w) or [beta, inf) (u = beta/w). Two assemblies:
// - whole (jump apart): on each piece (F(s) - F(t))/(t - s), a polynomial in s over the pole
//   factor, plus (F_top - F_flank)(t) Lambda/(2v), Lambda = log|(v + beta)/(v - beta)|, written
//   D~(t) (t + beta^2) Psi(a, b, a - b)/(2 beta) with D~ = (F_top - F_flank)/(t - beta^2) rational
//   (the slopes meet at beta^2) and a = (1 - Cx)(1 + c), b = (1 - c)(1 + Cx), a - b = 2 (c - Cx)
//   (c = cos x^ at the branch, a/b = t/beta^2): one expression over the whole period, finite at
//   the branch point, at the top (a = 0) and at the bottom (b = 0) of the profile; its terms
//   cancel where t nears a pole of the other branch's formula;
// - one side (Cauchy kept): the own piece as above with F_own(t) times its principal value,
//   the other piece with its Cauchy factor beside its pole factor (J_{j,L}): no cancellation at
//   the other branch's poles, the two pieces' logarithms cancelling at the branch point instead.
#pragma once

#include <ginac/ginac.h>

namespace wavecontact::derive {

// Psi(a, b, a - b) = ((a - b)/(a + b)) sqrt(b/a) log|(sqrt a + sqrt b)/(sqrt a - sqrt b)|,
// a, b >= 0, a + b > 0, as conjugate_logarithm(a, b, a_minus_b) with a - b written without
// cancellation (the runtime's wavecontact/detail/conjugate_logarithm.hpp): 0 at a = b and at b = 0,
// -2 at a = 0. Numerical evaluation at GiNaC::Digits.
DECLARE_FUNCTION_3P(conjugate_logarithm)

// p_fc(x) for the profile y(x^) = R(Cx) (rational in sym::Cx() and the parameters, its
// poles in t at roots of factors linear in t, none on t >= 0), as an expression in
// sym::E(), sym::b1(), sym::Cx() and the parameters, with sqrt(-tau) of every pole.
// Throws std::invalid_argument if a denominator factor is not linear in t.
GiNaC::ex full_contact_pressure(const GiNaC::ex& R);

// p_fc(x) for a profile built with abs(): R_top(Cx) for Cx >= cosine, R_flank(Cx) below,
// continuous with their slopes at Cx = cosine (-1 < cosine < 1, beta = tan(x^/2) there
// rational), their poles off the period. The whole form, in sym::E(), sym::b1(), sym::Cx() and
// the parameters, with I_{j,l} and Psi atoms. Throws std::invalid_argument if a branch's slope
// has more than one pole factor or one not linear in t, std::logic_error if the branches or
// their slopes do not meet.
GiNaC::ex full_contact_pressure(const GiNaC::ex& R_top, const GiNaC::ex& R_flank, const GiNaC::numeric& cosine);

// The same on one side of the branch point (top: Cx > cosine, else Cx < cosine), the other
// piece's Cauchy factor kept (J_{j,l}): well conditioned where the point meets a pole of the
// other branch's formula (cos x^ = 1/m of eq. 2's flank for m > 1, on the top side). At the
// branch point itself its logarithms are infinite.
GiNaC::ex full_contact_pressure_on_side(const GiNaC::ex& R_top, const GiNaC::ex& R_flank, const GiNaC::numeric& cosine,
                                        bool top);

}  // namespace wavecontact::derive
