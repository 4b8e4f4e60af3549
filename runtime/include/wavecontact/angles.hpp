// The angle atoms in which the generated evaluators are written (see generated/), with
// a^ = pi a/b1 and x^ = pi x/b1:
//   Ca = cos a^, Sa = 1 - cos a^, Cx = cos x^, Sx = 1 - cos x^, D = cos x^ - cos a^.
// Each is computed without cancellation: Sa = 2 sin^2(a^/2), and
// D = 2 sin((a^+x^)/2) sin((a^-x^)/2) with a - x formed in physical units first, so
// the pressure keeps full relative accuracy as x -> a.
#pragma once

namespace wavecontact {

struct ZoneAngles {
  double Ca, Sa;
};

struct PointAngles {
  double Cx, Sx, D;
};

// For the contact half-width a, 0 <= a <= b1 (else std::domain_error).
ZoneAngles zone_angles(double a, double b1);

// For a point 0 <= x <= a of the zone (else std::domain_error).
PointAngles point_angles(double x, double a, double b1);

// x reduced to the period [-b1, b1] centred on an asperity's top.
double reduce_to_period(double x, double b1);

}  // namespace wavecontact
