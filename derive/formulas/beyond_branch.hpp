// A contact zone that reaches a change of branch of its profile: the |cos x^| of eq. 2 at
// x^ = pi/2 (v = 1) beyond a = b1/2, or the sign change of any abs() in a user's profile
// (branches.hpp). The right-hand side of eq. 5 is then g_top on |v| < beta and g_flank
// beyond, and the load and its slope are sums of the sub-interval moments of the two pieces
// (sub_interval.hpp). One derivation for the built-in curve and for user profiles.
#pragma once

#include <vector>

#include <ginac/ginac.h>

#include "engine/sub_interval.hpp"

namespace wavecontact::derive {

struct BeyondBranch {
  GiNaC::ex beta;            // v = tan(x^/2) at the change of branch
  GiNaC::ex top_g, flank_g;  // eq. 11 of each branch, rational in sym::v()
  // The load (eq. 6 by docs/mathematics.md fact 7, load_integrand) for beta < alpha: in v-variables and
  // in angle atoms.
  std::vector<MomentTerm> load_v, load_angle;
  // As the zone's edge comes down to the branch the top piece [0, beta] is nearly the whole
  // (its argument z of I_{j,l} grows without bound): the same load with that piece in
  // large_argument_form, and the argument, in angle atoms, whose value >= 1 selects it.
  std::vector<MomentTerm> load_near_branch_angle;
  GiNaC::ex top_piece_argument;
  // The slope factor dP/da^ / sin(a^) = dP/dSa - dP/dCa in angle atoms, two ways: the
  // derivative of load_angle, whose terms grow like (cos x^_branch - cos a^)^(-1/2) and cancel
  // as a^ comes down to the branch, for z < 0; and the moments of load_slope_integrand (by
  // parts, no end point differentiated), in v-variables and in angle atoms, whose pieces carry
  // the jump of g' at the branch and cancel where the zone reaches well beyond it, for z >= 0.
  std::vector<MomentTerm> load_slope_factor;
  std::vector<MomentTerm> load_slope_factor_by_parts_v, load_slope_factor_by_parts;
  // The pressure p(x) (eq. 12, physical units) at a point on one branch ("own"; the top,
  // |u| < beta, or the flank), in v-variables and in angle atoms: the moment of the own piece
  // (t - s divided out) plus that of the other piece, either with the Cauchy factor 1/(t - s)
  // beside the other branch's pole factor (other_cauchy: J_{j,l} atoms, whose terms cancel
  // like log(1 + y) near the branch), or with the jump f_other(s) - f_own(s) apart (other +
  // jump: coefficients with the other branch's pole at s instead). Each piece comes in the
  // I_{j,l} and in the edge basis I'_{j,l}, J'_{j,l} (sub_interval.hpp), for its pole factor's
  // argument >= 0 and < 0 (own_argument, other_argument).
  struct SidePressure {
    std::vector<MomentTerm> own, own_edge, other_cauchy, other_cauchy_edge, other, other_edge, jump;
    GiNaC::ex own_argument, other_argument;
  };
  SidePressure pressure_top_v, pressure_flank_v, pressure_top, pressure_flank;
};

// The forms above for g_top on [0, beta], g_flank on [beta, alpha]. `sample` gives every
// parameter a value; the signs of the angle forms are fixed there at alpha = 3 beta/2.
// Throws std::invalid_argument where sub_interval.hpp does (a moment whose integrand has
// more than one pole factor in v^2).
BeyondBranch derive_beyond_branch(const GiNaC::ex& top_g, const GiNaC::ex& flank_g, const GiNaC::ex& beta,
                                  const GiNaC::exmap& sample);

// `sample` with alpha = 3 beta/2 and no point u in the zone: where the angle forms beyond the
// branch have their signs fixed.
GiNaC::exmap sample_beyond_branch(GiNaC::exmap sample, const GiNaC::ex& beta);

}  // namespace wavecontact::derive
