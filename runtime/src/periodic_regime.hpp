// The parametric wave curve beyond a = b1/2 (the "periodic regime" of the seed's Fig. 5b):
// the zone reaches the |cos| branch of eq. 2, so the right-hand side of eq. 5 is
//   g(v) = E* H1 (m+1) v (1+v^2) / (1 + v^2 + m |1 - v^2|)^2,
// piecewise rational with a kink in its slope at v = +-1 (cos x^ = 0). The pressure is
// evaluated by the quadrature of kinked_inversion.hpp. Normalised: b1 = pi, H1 = E* = 1;
// angles are passed as half-angle sines and cosines so that nothing cancels. The load and
// its slope have closed forms (derive/sub_interval.hpp).
#pragma once

#include "kinked_inversion.hpp"
#include "wavecontact/angles.hpp"
#include "wavecontact/parameters.hpp"

namespace wavecontact::detail {

// p^(x^) of eq. 12 for the zone `zone` at the point with half-angles `point`,
// 0 <= x^ < a^. D = cos x^ - cos a^ (computed without cancellation by the caller).
double periodic_pressure(double m, HalfAngles zone, HalfAngles point, double D);

// F = dP/dSa - dP/dCa of the exact load, 0 < a <= b1, from the closed forms on either side of
// b1/2 (generated/waviness.hpp): dP/da = (pi/b1) sin(pi a/b1) F (waviness.cpp).
double load_slope_factor(const WavinessParams& params, double a);

// The exact load for b1/2 < a <= b1 from its closed forms (waviness.cpp).
double load_beyond_half(double E, double H1, double m, const ZoneAngles& zone);

}  // namespace wavecontact::detail
