// The density of one zone and its field (docs/contact.md):
//   q(t) = sum_{j=0}^{N} d_j T_j(tau) / sqrt(1 - tau^2),  tau = (t - m)/h,
// the unbounded basis, in which the logarithmic potential Psi(s) = -(1/pi) Int q(t) log|s - t| dt
// is exact in closed form: on the zone h [d_0 log(2/h) + sum_{j>=1} d_j T_j(tau)/j] (the
// zone's own operator is diagonal), off it, with zeta = z - sgn(z) sqrt(z^2 - 1) (|zeta| < 1),
//   Psi = h [d_0 (log(2/h) + log|zeta|) + sum_{j>=1} d_j zeta^j / j],
//   dPsi/ds = -(d_0 + sum_{j>=1} d_j zeta^j) / (sgn(z) sqrt(z^2 - 1)).
// The zone carries pi h d_0 (of P/2), and q is bounded at an end (the pressure vanishes like a
// square root there) where sum_j d_j T_j(+-1) = 0.
#pragma once

#include <vector>

#include "zone.hpp"

namespace wavecontact::detail {

struct FieldValue {
  double potential = 0, slope = 0;  // Psi and dPsi/ds
};

// The field at the points of angles x[0 .. points) off the zone (not inside it) into out, of
// the density with coefficients d[0 .. count). Each point's series stops once its terms fall
// below 1e-17 of the sum.
void far_fields(const ZoneGeometry& g, const double* d, int count, const HalfAngle* x, std::size_t points,
                FieldValue* out);
// The same field, its potential as Psi(x_i) - Psi(reference) for points on the reference's
// side of the zone, from the points' offsets s_i - s_ref: without the rounding of Psi itself
// (about one ulp of each value, which a zone's coefficients j G_j / h multiply).
void far_field_differences(const ZoneGeometry& g, const double* d, int count, const HalfAngle& reference,
                           const HalfAngle* x, const double* from_reference, std::size_t points, FieldValue* out);
// The potential alone, the same.
double far_potential(const ZoneGeometry& g, const double* d, int count, const HalfAngle& x);

// log(2/h): the potential on the zone of the unit density T_0 / (h sqrt(1 - tau^2)).
double self_logarithm(const ZoneGeometry& g);

// The coefficients of the zone's own potential: o_0 = h log(2/h) d_0, o_j = h d_j / j.
void own_potential(const ZoneGeometry& g, const double* d, int count, double* o);

// The pressure in its bounded form, so that it keeps its digits as x nears an end: the root
// factored out at each bounded end, the coefficients d[0 .. count) (their end conditions met)
// recast in the basis that remains, V_j at the top, W_j at the valley, U_j between (T_j for a
// zone over the whole half period).
std::vector<double> bounded_pressure_series(const ZoneGeometry& g, const double* d, int count);
// The pressure (normalised: sin x^ q) at the angles x[0 .. points) in the zone, from that
// series, into p.
void zone_pressures(const ZoneGeometry& g, const std::vector<double>& series, const double* x, double* p,
                    std::size_t points);

}  // namespace wavecontact::detail
