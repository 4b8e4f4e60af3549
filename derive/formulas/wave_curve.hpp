// The parametric wave curve (eq. 2) through the engine: eq. 11, the exact eq. 13/14,
// the load (eq. 6), pa and pa/p*, and the printed eq. 13/14 of the seed for comparison.
#pragma once

#include <vector>

#include <ginac/ginac.h>

#include "engine/closed_forms.hpp"
#include "formulas/beyond_branch.hpp"

namespace wavecontact::derive {

// The closed forms of eq. 2 on the contact side (b1 -> pi, eq. 8): inversion is the exact
// eq. 13, pressure_angle the exact eq. 14.
struct WavinessDerivation : ClosedForms {
  RadicalSum paper_inversion;  // printed eq. 13, same convention
  RadicalSum paper_load;       // eq. 6 applied to the printed eq. 13
  std::vector<RootTerm> paper_pressure_v, paper_pressure_angle;
  // pa/p* = P / (pi E* H1), dimensionless.
  std::vector<RootTerm> pa_over_pstar_v, pa_over_pstar_angle;
  // Beyond a = b1/2 the zone reaches the |cos| branch of eq. 2 at v = 1 (x^ = pi/2): flank_g is
  // eq. 11 of the branch cos x^ <= 0, y = H1 (m+1) cos x^/(1 - m cos x^).
  BeyondBranch beyond_half;
};

// y(x^) = H1 (m+1) cos x^ / (m cos x^ + 1): the analytic branch of eq. 2 (cos >= 0).
GiNaC::ex parametric_wave_curve();

// The printed eq. 13 of the seed: p^(u) = sqrt(alpha^2 - u^2) * R(s) / sqrt(alpha^2 + 1);
// returns R.
GiNaC::ex printed_eq13_rational();

WavinessDerivation derive_waviness();

}  // namespace wavecontact::derive
