// The engine over part of a contact zone: weighted moments over sub-intervals of
// [-alpha, alpha], for profiles that change branch inside the zone (the |cos x| of eq. 2
// at x = b1/2, v = 1).
//
//   M_[0,beta][Phi]     = (2/pi) Int_0^beta     Phi(v^2)/sqrt(alpha^2 - v^2) dv,
//   M_[beta,alpha][Phi] = (2/pi) Int_beta^alpha Phi(v^2)/sqrt(alpha^2 - v^2) dv,
//
// together the whole moment M of hilbert.hpp. With v = alpha sin(phi) and T = tan(phi) on
// [0, beta] (T = cot(phi) on [beta, alpha]) each is (2/pi) Int_0^T0 Psi(T^2) dT for a rational
// Psi, T0 = beta/sqrt(alpha^2 - beta^2) (its inverse on [beta, alpha]). A Psi whose
// denominator is c (a + b S)^l in S = T^2 integrates termwise to
//   Int_0^T0 S^j/(a + b S)^l dT = T0^(2j+1) a^-l I_{j,l}(b T0^2/a),
// I_{j,l}(z) = Int_0^1 w^(2j)/(1 + z w^2)^l dw (runtime/include/wavecontact/detail/quadratic_moment.hpp),
// with no coefficient singular where b -> 0 (the pole passing through infinity).
#pragma once

#include <vector>

#include <ginac/ginac.h>

namespace wavecontact::derive {

// I_{j,l}(z) as quadratic_moment(j, l, z, w), w = 1 + z written without cancellation (the
// emitted code passes both): a GiNaC function with dI/dz = -l I_{j+1,l+1} (w follows z) and
// numerical evaluation at GiNaC::Digits (series for |z| <= 1/10, atan or atanh otherwise).
DECLARE_FUNCTION_4P(quadratic_moment)

// J_{j,l}(y, z) = Int_0^1 w^(2j)/((1 + y w^2)(1 + z w^2)^l) dw as two_factor_moment(j, l, y,
// 1 + y, z, 1 + z): the atom where the integrand has a Cauchy factor 1/(t - s) (argument y)
// beside a pole factor (argument z), the pressure's moments beyond a change of branch. Numerical
// evaluation at GiNaC::Digits by partial fractions with the digits they cancel added, or by its
// Taylor series in y - z where y and z nearly coincide.
DECLARE_FUNCTION_6P(two_factor_moment)

// I'_{j,l}(z) = Int_0^1 (1 - w^2)^j/(1 + z w^2)^l dw as edge_moment(j, l, z, 1 + z): the
// moments in powers of 1 - w^2 (the runtime's wavecontact::edge_moment), which keep their digits
// where z -> -1 (a pole just beyond the sub-interval's end) and the I_{j,l} all tend to one
// value. Numerical evaluation from the I_{j,l} with the digits their sum cancels added.
DECLARE_FUNCTION_4P(edge_moment)

// J'_{j,l}(y, z) = Int_0^1 (1 - w^2)^j/((1 + y w^2)(1 + z w^2)^l) dw as two_factor_edge_moment(j,
// l, y, 1 + y, z, 1 + z): the two-factor moment in the edge basis (the runtime's function of that
// name). Numerical evaluation from the J_{i,l} with the digits their sum cancels added.
DECLARE_FUNCTION_6P(two_factor_edge_moment)

// One term c sqrt(r) I_{j,l}(z) of a sub-interval moment (c sqrt(r) alone if l = 0), c, r,
// z and one_plus_z = 1 + z rational in sym::alpha() and the parameters; with a Cauchy factor
// (cauchy set, its argument y rational in sym::s() too), c sqrt(r) J_{j,l}(y, z); in the edge
// basis (edge set), c sqrt(r) I'_{j,l}(z) or J'_{j,l}(y, z).
struct MomentTerm {
  GiNaC::ex rational, radicand;
  int j = 0, l = 0;
  GiNaC::ex z, one_plus_z;
  bool cauchy = false;
  GiNaC::ex y, one_plus_y;
  bool edge = false;
};

// A term without a Cauchy factor.
MomentTerm moment_term(GiNaC::ex rational, GiNaC::ex radicand, int j, int l, GiNaC::ex z, GiNaC::ex one_plus_z);

// The same moment where z -> +infinity (the sub-interval reaching the whole): for l > j,
//   I_{j,l}(z) = K_{j,l} z^-(j+1/2) - z^-l I_{l-j-1,l}(1/z),  K_{j,l} = Int_0^inf s^2j/(1+s^2)^l ds,
// so that c sqrt(r) z^-(j+1/2), finite where the sub-interval grows to the whole, is one term
// and the rest is small. Valid for z > 0; the term itself if l <= j or l = 0.
std::vector<MomentTerm> large_argument_form(const MomentTerm& term);

// The term's atom I_{j,l}(z), J_{j,l}(y, z), I'_{j,l}(z) or J'_{j,l}(y, z) (1 if l = 0 and no
// Cauchy factor): as_ex(term) = rational sqrt(radicand) moment_atom(term).
GiNaC::ex moment_atom(const MomentTerm& term);

// The term as an expression, and the sum of terms.
GiNaC::ex as_ex(const MomentTerm& term);
GiNaC::ex as_ex(const std::vector<MomentTerm>& terms);

// M_[0,beta][Phi] and M_[beta,alpha][Phi] for Phi rational in sym::t() (beta a symbol or a
// number, 0 < beta < sym::alpha()), as sums of terms. Phi may have the Cauchy factor t - s
// (sym::s() off the sub-interval) beside one pole factor. With edge_basis, the terms with a pole
// factor are written in I'_{j,l} or J'_{j,l} (the numerator in powers of 1 - w^2). Throws
// std::invalid_argument if Psi's denominator has any other factor depending on S.
std::vector<MomentTerm> inner_moment(const GiNaC::ex& Phi, const GiNaC::ex& beta, bool edge_basis = false);
std::vector<MomentTerm> outer_moment(const GiNaC::ex& Phi, const GiNaC::ex& beta, bool edge_basis = false);

// Eq. 6 from the right-hand side g of eq. 5 alone (docs/mathematics.md fact 7 in v = tan(x^/2)):
//   P = 2 pi sqrt(1 + alpha^2) M[v g(v)/(1 + v^2)],
// so that a piecewise g needs only the moments of its pieces.
GiNaC::ex load_integrand(const GiNaC::ex& g);

// The slope of eq. 6 from g alone: with G = g(v(x^)), integration by parts in docs/mathematics.md fact 7
// (G(0) = 0) gives P = 2 sqrt2 Int_0^a^ sqrt(cos x^ - cos a^) (G/cos(x^/2))' dx^, whose
// derivative differentiates no end point:
//   dP/da^ = sin(a^) (pi/2) sqrt(1 + alpha^2) M[(1 + v^2) g'(v) + v g(v)].
// Returns the integrand in sym::t(); g may have a kink (its pieces' moments add up).
GiNaC::ex load_slope_integrand(const GiNaC::ex& g);

}  // namespace wavecontact::derive
