// A profile through the engine, the same way for the built-in wave curve and for a
// user's profile: eq. 11 (g from the profile), eq. 12 (the bounded inversion), eq. 6 (the
// load), each also in the angle atoms of eq. 14.
#pragma once

#include <vector>

#include <ginac/ginac.h>

#include "engine/angle_form.hpp"
#include "engine/radicals.hpp"
#include "profile/harmonic_part.hpp"

namespace wavecontact::derive {

// y = sum_k cosine[k] cos(k x^) + R(cos x^) (harmonic_part.hpp): the cosine sum has the
// Legendre-Dirichlet form; g, the inversion, the load and their forms below are those of
// R, the part whose poles lie off v^2 = -1 (the whole profile when cosine is empty).
struct ClosedForms {
  Radicals radicals;
  GiNaC::ex profile;              // y(x^), even in sym::x(), rational in cos(k x^), sin(k x^)
  std::vector<GiNaC::ex> cosine;  // A_0..A_K, or empty
  GiNaC::ex g;                    // eq. 11: g(v) = -(E*/2) R'(x^(v))
  RadicalSum inversion;           // eq. 12 solved: p^(u) = sqrt(alpha^2 - u^2) * inversion(s)
  RadicalSum load;                // eq. 6: P(alpha)
  // In physical units, p(x) = (pi/b1) p^(x^); v-form and angle form.
  std::vector<RootTerm> pressure_v, pressure_angle;
  std::vector<RootTerm> load_v, load_angle;
  // dP/dSa - dP/dCa of the angle form: dP/da^ = sin(a^) * load_slope_factor.
  std::vector<RootTerm> load_slope_factor;
  // The profile in s = cos x^ (sym::Cx()), y(x^) = Y(cos x^), and dY/ds: the surface as the
  // multi-zone contact solver of the runtime sees it (runtime/src/contact/surface_model.hpp).
  GiNaC::ex height, height_slope;
  GiNaC::ex rational_height, rational_height_slope;  // R(Cx) and dR/dCx
  long harmonic = 1;                                 // the degree of Y in cos x^: the highest k of its harmonics
};

// Every term of a closed form in angle atoms (signs fixed at `sample`).
std::vector<RootTerm> in_angles(const std::vector<RootTerm>& v_form, const GiNaC::exmap& sample = sample_point_v());

// dF/dSa - dF/dCa of one term c sqrt(r): [(Dc r + c Dr / 2) / r] sqrt(r), so that
// dF/da^ = sin(a^) times it.
RootTerm slope_factor(const RootTerm& term);

// Every term's rational part multiplied by factor.
std::vector<RootTerm> scaled(std::vector<RootTerm> terms, const GiNaC::ex& factor);

// Derives every closed form of the profile y (a GiNaC expression in sym::x()), split by
// split_harmonic_part. Throws std::invalid_argument if y is not rational in cos(k x^),
// sin(k x^) or not even.
ClosedForms derive_closed_forms(const GiNaC::ex& y, const GiNaC::exmap& sample = sample_point_v());
// The same with the parts given: {{}, in_cosine(y)} sends the whole profile through the
// partial fractions of the engine (the proofs of the Legendre-Dirichlet form compare both).
ClosedForms derive_closed_forms(const GiNaC::ex& y, const HarmonicSplit& parts,
                                const GiNaC::exmap& sample = sample_point_v());

}  // namespace wavecontact::derive
