// Full contact (a = b1, MATH.md fact 11) in closed form: p = pa + p_fc, where for
// y = sum_k y_k cos(k x^)
//   p_fc(x) = (E*/2)(pi/b1) sum_k k y_k cos(k x^) = (E*/2)(pi/b1) d(y~)/dx^,
// y~ the conjugate function of y. Under v = tan(x^/2) (eq. 4) the conjugate function is the
// Hilbert transform on the line, y~(v) = H[Y](v) = (1/pi) PV Int Y(u^2)/(v - u) du for
// y(x^) = Y(t), t = v^2, and for a pole 1/(t - tau), tau < 0, H = v/(sqrt(-tau)(v^2 - tau)):
// so H[Y] is the sum over Y's poles of the residues at t = tau of Y(t) v/(sqrt(-t)(v^2 - t)),
// taken from the Taylor series at tau (with 1/sqrt(-t) = (1/sqrt(-tau)) (1 + h/tau)^(-1/2),
// h = t - tau). A cosine sum's part is the sum itself (harmonic_series.hpp).
//
// A profile built with abs() (branches.hpp) is Y_top on t < beta^2 and Y_flank beyond. Over
// each piece, with Y = C + sum c_{tau,l}/(t - tau)^l and, for x = u^2, A = v^2,
//   1/((A - x)(x - tau)^l) = 1/((A - tau)^l (A - x)) + sum_{i=1..l} 1/((A - tau)^(l+1-i) (x - tau)^i),
// the Hilbert transform H = (1/pi) Int_piece Y(u^2) 2v/(v^2 - u^2) du is elementary:
//   pi H = D(t) Lambda(v) + v rho(t),  D = Y_top - Y_flank,  Lambda = log|(v + beta)/(v - beta)|,
//   rho = 2 sum_pieces sum_{tau,l} c_{tau,l} sum_{i=1..l} B_i(tau)/(t - tau)^(l+1-i),
//   B_i = Int_piece du/(u^2 - tau)^i:  beta (-tau)^-i I_{0,i}(-beta^2/tau) on [0, beta],
//                                      beta^(1-2i) I_{i-1,i}(-tau/beta^2) on [beta, inf),
// (I_{j,l} of sub_interval.hpp; the pieces of Lambda from the end at infinity vanish), so
//   p_fc = (E*/(4 b1)) (1 + t) [2 v Lambda D'(t) - 2 beta D(t)/(t - beta^2) + rho + 2 t rho'(t)].
// D and D' vanish at beta^2 (the slopes meet there), so D/(t - beta^2) is rational and
//   v Lambda D' = beta D'(t) (t + beta^2)/(t - beta^2) Xi(a, b, a - b),
// with a = (1 - Cx)(1 + c), b = (1 - c)(1 + Cx), a - b = 2 (c - Cx) (c = cos x^ at the
// branch, a/b = t/beta^2) and the bounded atom Xi below: finite at the branch point, at the
// top (a = 0) and at the bottom (b = 0) of the profile.
#pragma once

#include <ginac/ginac.h>

namespace wavecontact::derive {

// Xi(a, b, a - b) = ((a - b)/(a + b)) sqrt(a/b) log|(sqrt a + sqrt b)/(sqrt a - sqrt b)|,
// a, b >= 0, a + b > 0, as conjugate_logarithm(a, b, a_minus_b) with a - b written without
// cancellation: 0 at a = b and at a = 0, 2 at b = 0. Numerical evaluation at GiNaC::Digits.
DECLARE_FUNCTION_3P(conjugate_logarithm)

// p_fc(x) for the profile y(x^) = R(Cx) (rational in sym::Cx() and the parameters, its
// poles in t at roots of factors linear in t, none on t >= 0), as an expression in
// sym::E(), sym::b1(), sym::Cx() and the parameters, with sqrt(-tau) of every pole.
// Throws std::invalid_argument if a denominator factor is not linear in t.
GiNaC::ex full_contact_pressure(const GiNaC::ex& R);

// p_fc(x) for a profile built with abs(): R_top(Cx) for Cx >= cosine, R_flank(Cx) below,
// continuous with their slopes at Cx = cosine (-1 < cosine < 1, beta = tan(x^/2) there
// rational), their poles off the period. One expression for the whole period, in sym::E(),
// sym::b1(), sym::Cx() and the parameters, with I_{j,l} and Xi atoms. Throws
// std::invalid_argument if a denominator factor is not linear in t, std::logic_error if the
// branches or their slopes do not meet.
GiNaC::ex full_contact_pressure(const GiNaC::ex& R_top, const GiNaC::ex& R_flank, const GiNaC::numeric& cosine);

// The same on one side of the branch point, well conditioned where the point meets a pole of
// the other branch's formula (which lies on this side, as cos x^ = 1/m of eq. 2's flank does
// for m > 1): by p_fc = (E*/b1)(1 + t) Int_0^inf F(u^2)/(t - u^2) du, F = t Y'(t) (the
// conjugate of the slope; no derivative of an atom), the own piece by partial fractions with
// F(t) apart, the other with its Cauchy factor kept beside each pole factor (J_{j,l} of
// sub_interval.hpp). R_own on the side (Cx > cosine for top, Cx < cosine otherwise), R_other
// beyond. At Cx = cosine itself the atoms' logarithms are infinite: the whole form holds there.
GiNaC::ex full_contact_pressure_on_side(const GiNaC::ex& R_own, const GiNaC::ex& R_other,
                                        const GiNaC::numeric& cosine, bool top);

}  // namespace wavecontact::derive
