// The parametric wave curve beyond a = b1/2 (the "periodic regime" of the seed's Fig. 5b):
// the zone reaches the |cos| branch of eq. 2, so the right-hand side of eq. 5 is
//   g(v) = E* H1 (m+1) v (1+v^2) / (1 + v^2 + m |1 - v^2|)^2,
// piecewise rational with a kink in its slope at v = +-1 (cos x^ = 0). The pressure, the load
// and its slope have closed forms (derive/formulas/beyond_branch.hpp, derive/engine/sub_interval.hpp).
#pragma once

#include <cstddef>

#include "closed_forms/kinked_inversion.hpp"
#include "wavecontact/angles.hpp"
#include "wavecontact/parameters.hpp"

namespace wavecontact::detail {

// p(x) in physical units from the closed forms (generated/waviness_evaluators.hpp), for b1/2 < a < b1 and
// a point 0 <= x^ < a^.
double pressure_beyond_half(const WavinessParams& params, const ZoneAngles& zone, const PointAngles& point);

// The same for many points of one zone: both sides of the kink with the zone's atoms kept.
class BeyondHalfZone {
 public:
  BeyondHalfZone(const WavinessParams& params, const ZoneAngles& zone);
  // p at the points x (reduced to the period; 0 outside the zone |x| < a), with the atoms of the
  // Cauchy part tabulated over the points that take it (BranchSide::tabulate_cauchy), in chunks
  // on threads from min_points on (parallel.hpp).
  void pressures(double a, double b1, const double* x, double* p, std::size_t count, std::size_t min_points);
  // p at one point of the zone, 0 <= x^ < a^ (pressure_beyond_half's value).
  double pressure(const PointAngles& point) const;

 private:
  const BranchSide& side(const PointAngles& point) const { return point.Cx >= 0 ? top_ : flank_; }

  double m_;
  BranchSide top_, flank_;
};

// F = dP/dSa - dP/dCa of the exact load, 0 < a <= b1, from the closed forms on either side of
// b1/2 (generated/waviness_evaluators.hpp): dP/da = (pi/b1) sin(pi a/b1) F (waviness.cpp).
double load_slope_factor(const WavinessParams& params, double a);

// The exact load for b1/2 < a <= b1 from its closed forms (waviness.cpp).
double load_beyond_half(double E, double H1, double m, const ZoneAngles& zone);

}  // namespace wavecontact::detail
