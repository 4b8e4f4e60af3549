// The parametric wave curve (eq. 2) through the engine: eq. 11, the exact eq. 13/14,
// the load (eq. 6), pa and pa/p*, and the printed eq. 13/14 of the seed for comparison.
#pragma once

#include <vector>

#include <ginac/ginac.h>

#include "angle_form.hpp"
#include "radicals.hpp"

namespace wavecontact::derive {

struct WavinessDerivation {
  Radicals radicals;
  GiNaC::ex profile;        // y(x^) on the contact side, eq. 2 with b1 -> pi (eq. 8)
  GiNaC::ex g;              // eq. 11: g(v) = -(E*/2) y'(x^(v))
  RadicalSum inversion;     // exact eq. 13: p^(u) = sqrt(alpha^2 - u^2) * inversion(s)
  RadicalSum paper_inversion;  // printed eq. 13, same convention
  RadicalSum load;          // exact eq. 6: P(alpha)
  RadicalSum paper_load;    // eq. 6 applied to the printed eq. 13
  // Angle (eq. 14) forms, in physical units: p(x) = (pi/b1) p^(x^).
  std::vector<RootTerm> pressure_v, pressure_angle;
  std::vector<RootTerm> paper_pressure_v, paper_pressure_angle;
  std::vector<RootTerm> load_v, load_angle;
  // pa/p* = P / (pi E* H1), dimensionless.
  std::vector<RootTerm> pa_over_pstar_v, pa_over_pstar_angle;
};

// y(x^) = H1 (m+1) cos x^ / (m cos x^ + 1): the analytic branch of eq. 2 (cos >= 0).
GiNaC::ex parametric_wave_curve();

// The printed eq. 13 of the seed: p^(u) = sqrt(alpha^2 - u^2) * R(s) / sqrt(alpha^2 + 1);
// returns R.
GiNaC::ex printed_eq13_rational();

WavinessDerivation derive_waviness();

}  // namespace wavecontact::derive
