// The one engine for the bounded inversion of the finite Hilbert transform (eq. 12)
// and for the load integral (eq. 6). Every closed form of wavecontact comes from here.
//
// Everything reduces to the weighted moment
//   M[Phi] = (1/pi) Int_{-alpha}^{alpha} Phi(v^2) / sqrt(alpha^2 - v^2) dv
// of a rational Phi(t) whose poles in t = v^2 lie off [0, alpha^2]. Partial fractions
// in t leave a polynomial part, with moments alpha^{2k} C(2k,k)/4^k, and pole parts
// 1/(t - tau)^l, whose moments are derivatives in tau of
//   E1(tau) = M[1/(t - tau)] = -1/(tau kappa(tau)),  kappa(tau) = sqrt(1 - alpha^2/tau).
// Each pole's contribution is the residue at t = tau of Phi(t) E1(t), taken from the
// Taylor series of E1 at tau (a three-term recurrence, no symbolic derivatives).
#pragma once

#include <ginac/ginac.h>

#include "engine/radicals.hpp"

namespace wavecontact::derive {

// M[Phi] for Phi a rational function of sym::t() (other symbols are parameters; the
// coefficients may already carry radicals, which are constants here).
// Throws std::invalid_argument if a denominator factor is not linear in t.
RadicalSum weighted_moment(const RadicalSum& Phi, Radicals& radicals);

// Eq. 12. For an odd rational g(v) (sym::v()), the bounded solution of eq. 5 is
//   p(u) = sqrt(alpha^2 - u^2) I(s),  s = u^2,
// and this returns I as a function of sym::s(). Uses
//   I = M[(v g(v) - u g(u)) / (v^2 - u^2)]  (the Cauchy kernel's odd part integrates to 0).
// Throws std::invalid_argument if g is not odd or not rational in v.
RadicalSum bounded_inversion(const GiNaC::ex& g, Radicals& radicals);

// Eq. 6: P = Int_{-alpha}^{alpha} 2 p(u)/(1 + u^2) du for p = sqrt(alpha^2 - u^2) I(s).
RadicalSum load_integral(const RadicalSum& I, Radicals& radicals);

// An even polynomial or rational function of v, rewritten in t = v^2.
// Throws std::invalid_argument if it is not even.
GiNaC::ex even_in_square(const GiNaC::ex& e, const GiNaC::symbol& v, const GiNaC::symbol& t);

}  // namespace wavecontact::derive
