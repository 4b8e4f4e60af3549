// The well-conditioned form of the closed forms (the paper's eq. 14 variables).
//
// The engine's closed forms live in v-variables: s = u^2 = tan^2(x^/2) and
// alpha^2 = tan^2(a^/2). They lose digits near the contact edge (alpha^2 - u^2) and for
// large m near a = b1/2 ((m+1) + (1-m) alpha^2). Rewritten in the angle atoms
//   Ca = cos a^, Sa = 1 - cos a^, Cx = cos x^, Sx = 1 - cos x^, D = cos x^ - cos a^
// (which the runtime computes without cancellation), every factor becomes either an
// atom or a polynomial in Ca, Cx and the parameters, e.g.
//   alpha^2 - u^2 = 2 D / ((1 + Cx)(1 + Ca)),  (m+1) + (1-m) alpha^2 = 2 (1 + m Ca)/(1 + Ca).
#pragma once

#include <vector>

#include <ginac/ginac.h>

#include "engine/radicals.hpp"

namespace wavecontact::derive {

// A closed form c * sqrt(r): c and r rational in the variables of one form.
struct RootTerm {
  GiNaC::ex rational;
  GiNaC::ex radicand;
};

// The terms of sqrt(prefactor_square) * closed (a RadicalSum), in v-variables.
std::vector<RootTerm> root_terms(const RadicalSum& closed, const Radicals& radicals,
                                 const GiNaC::ex& prefactor_square = 1);

// A point of the domain (0 < x^ < a^ < pi/2, m > 0, positive physical parameters) in
// v-variables, used to fix signs of square roots.
GiNaC::exmap sample_point_v();

// One term in angle atoms: substituted, factored over Q, squares pulled out of the
// root, factors (1 - Ca), (1 - Cx), (Cx - Ca) replaced by Sa, Sx, D. Each factor is
// oriented to be positive at `sample`, which must give every parameter a value.
RootTerm to_angle_atoms(const RootTerm& term, const GiNaC::exmap& sample = sample_point_v());

// The expression c * sqrt(r) of a term (sqrt omitted when r = 1).
GiNaC::ex as_ex(const RootTerm& term);

// Proof that an angle-form term equals its v-form term: c^2 r agree as rational
// functions after the atoms are written back in u and alpha, and the signs agree at a
// point of the domain. Returns the normal form of the difference of squares (zero when
// equal) and sets sign_agrees.
GiNaC::ex angle_form_residual(const RootTerm& v_form, const RootTerm& angle_form, bool& sign_agrees,
                              const GiNaC::exmap& sample = sample_point_v());

// The atoms written back in u (via s) and alpha.
GiNaC::ex atoms_in_v_variables(const GiNaC::ex& e);

}  // namespace wavecontact::derive
