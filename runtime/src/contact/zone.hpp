// One contact zone of the half period, [a, b] in x^ (0 <= a < b <= pi; a = 0: through the
// top, b = pi: through the valley), and where it lies in s = cos x^ (docs/contact.md):
// s in [cos b, cos a], centre m and half-width h, tau = (s - m)/h in [-1, 1] (tau = +1 at
// x^ = a). Every difference of points is formed from angles, without cancellation:
// cos x - cos y = -2 sin((x + y)/2) sin((x - y)/2).
#pragma once

#include <vector>

namespace wavecontact::detail {

// A point x^ with sin(x^/2) and cos(x^/2), from which its distances to zone ends are formed.
struct HalfAngle {
  double x = 0, sin_half = 0, cos_half = 1;
  static HalfAngle of(double x);
};

struct ZoneGeometry {
  ZoneGeometry() = default;
  ZoneGeometry(double a, double b);

  double a = 0, b = 0;  // the ends in x^
  double h = 0, m = 0;  // half-width and centre in s
  HalfAngle end_a, end_b;
  bool top() const { return a == 0; }
  bool valley() const;
  // How many ends are free (inside (0, pi)): the zone's conditions on them.
  int free_ends() const { return (top() ? 0 : 1) + (valley() ? 0 : 1); }

  // z - 1 and z + 1 at the point, z = (cos x - m)/h; z = (z - 1 + z + 1)/2. One sine each:
  // cos x - cos a = -2 sin((x + a)/2) sin((x - a)/2), the first factor from the half angles'
  // products (terms of one sign: no cancellation), the second, which vanishes at the end,
  // directly.
  double z_minus_1(const HalfAngle& p) const;
  double z_plus_1(const HalfAngle& p) const;

  // The angles of the points tau_i (decreasing tau: increasing x), without cancellation.
  std::vector<double> angles_of(const std::vector<double>& tau) const;

  // dh/da, dh/db, dm/da, dm/db.
  double dh_da() const, dh_db() const, dm_da() const, dm_db() const;
};

// cos x - cos y.
double cos_difference(double x, double y);

}  // namespace wavecontact::detail
