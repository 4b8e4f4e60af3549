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

// The same for the points of one zone, b1/2 < a < b1: both sides of the kink with the zone's atoms
// kept, and for each side a table of its Cauchy part's atoms (CauchyAtomTable), shared by the
// threads. A point's angles are those of the array kernels (simd_point_angles), so that one
// point and an array give the same bits.
class BeyondHalfZone {
 public:
  // Where the tables are built: `on_touch`, a panel the first time a point asks for it (every
  // value then a function of x alone, whatever came before: the WavinessZone kept for many
  // calls); otherwise only panels that at least CauchyAtomTable::nodes points of one call ask
  // for (an array evaluated once).
  BeyondHalfZone(const WavinessParams& params, double a, const ZoneAngles& zone, bool on_touch);
  // p at the points x (any period; 0 outside the zone), in chunks on threads from min_points on
  // (parallel.hpp).
  void pressures(const double* x, double* p, std::size_t count, std::size_t min_points) const;
  // p at one point x (any period).
  double pressure(double x) const;

 private:
  const BranchSide& side(const PointAngles& point) const { return point.Cx >= 0 ? top_ : flank_; }
  const CauchyAtomTable& table(const PointAngles& point) const { return point.Cx >= 0 ? top_table_ : flank_table_; }
  double pressure(const PointAngles& point, double eta) const;

  double m_, a_, b1_;
  bool on_touch_;
  BranchSide top_, flank_;
  CauchyAtomTable top_table_, flank_table_;
};

// F = dP/dSa - dP/dCa of the exact load, 0 < a <= b1, from the closed forms on either side of
// b1/2 (generated/waviness_evaluators.hpp): dP/da = (pi/b1) sin(pi a/b1) F (waviness.cpp).
double load_slope_factor(const WavinessParams& params, double a);

// The exact load for b1/2 < a <= b1 from its closed forms (waviness.cpp).
double load_beyond_half(double E, double H1, double m, const ZoneAngles& zone);

}  // namespace wavecontact::detail
