// The parametric wave curve (eq. 2) through the engine: eq. 11, the exact eq. 13/14,
// the load (eq. 6), pa and pa/p*, and the printed eq. 13/14 of the seed for comparison.
#pragma once

#include <vector>

#include <ginac/ginac.h>

#include "closed_forms.hpp"
#include "sub_interval.hpp"

namespace wavecontact::derive {

// The closed forms of eq. 2 on the contact side (b1 -> pi, eq. 8): inversion is the exact
// eq. 13, pressure_angle the exact eq. 14.
struct WavinessDerivation : ClosedForms {
  RadicalSum paper_inversion;  // printed eq. 13, same convention
  RadicalSum paper_load;       // eq. 6 applied to the printed eq. 13
  std::vector<RootTerm> paper_pressure_v, paper_pressure_angle;
  // pa/p* = P / (pi E* H1), dimensionless.
  std::vector<RootTerm> pa_over_pstar_v, pa_over_pstar_angle;
  // Beyond a = b1/2 the zone reaches the |cos| branch of eq. 2 at v = 1: the load is the sum
  // of the sub-interval moments (sub_interval.hpp) of the two branches' g, eq. 6 by MATH.md
  // fact 7 (load_integrand); in v-variables and in angle atoms.
  GiNaC::ex flank_g;  // eq. 11 of the branch cos x^ <= 0: y = H1 (m+1) cos x^/(1 - m cos x^)
  std::vector<MomentTerm> load_beyond_half_v, load_beyond_half_angle;
  // Near b1/2 the top piece [0, 1] of the zone is nearly the whole of it (its argument z of
  // I_{j,l} grows without bound): the same load with that piece in large_argument_form, and
  // the argument, in angle atoms, whose value >= 1 selects this form.
  std::vector<MomentTerm> load_near_half_angle;
  GiNaC::ex top_piece_argument;
  // The slope factor dP/da^ / sin(a^) = dP/dSa - dP/dCa in angle atoms: the derivative of
  // load_beyond_half_angle, for z < 0; and the moments of load_slope_integrand (by parts), in
  // v-variables and in angle atoms, for z >= 0 (derive_beyond_half says why).
  std::vector<MomentTerm> load_slope_factor_beyond_half;
  std::vector<MomentTerm> load_slope_factor_by_parts_v, load_slope_factor_by_parts;
};

// y(x^) = H1 (m+1) cos x^ / (m cos x^ + 1): the analytic branch of eq. 2 (cos >= 0).
GiNaC::ex parametric_wave_curve();

// The printed eq. 13 of the seed: p^(u) = sqrt(alpha^2 - u^2) * R(s) / sqrt(alpha^2 + 1);
// returns R.
GiNaC::ex printed_eq13_rational();

WavinessDerivation derive_waviness();

// A point of the domain beyond b1/2 (alpha = 3/2, m = 1/2): fixes the signs of the angle forms
// there.
GiNaC::exmap sample_point_beyond_half();

}  // namespace wavecontact::derive
