// The parametric wave curve beyond a = b1/2 (the "periodic regime" of the seed's Fig. 5b):
// the zone reaches the |cos| branch of eq. 2, so the right-hand side of eq. 5 is
//   g(v) = E* H1 (m+1) v (1+v^2) / (1 + v^2 + m |1 - v^2|)^2,
// piecewise rational with a kink in its slope at v = +-1 (cos x^ = 0). The pressure, the load
// and its slope have closed forms (derive/beyond_branch.hpp, derive/sub_interval.hpp).
#pragma once

#include "kinked_inversion.hpp"
#include "wavecontact/angles.hpp"
#include "wavecontact/parameters.hpp"

namespace wavecontact::detail {

// p(x) in physical units from the closed forms (generated/waviness.hpp), for b1/2 < a < b1 and
// a point 0 <= x^ < a^.
double pressure_beyond_half(const WavinessParams& params, const ZoneAngles& zone, const PointAngles& point);

// F = dP/dSa - dP/dCa of the exact load, 0 < a <= b1, from the closed forms on either side of
// b1/2 (generated/waviness.hpp): dP/da = (pi/b1) sin(pi a/b1) F (waviness.cpp).
double load_slope_factor(const WavinessParams& params, double a);

// The exact load for b1/2 < a <= b1 from its closed forms (waviness.cpp).
double load_beyond_half(double E, double H1, double m, const ZoneAngles& zone);

}  // namespace wavecontact::detail
