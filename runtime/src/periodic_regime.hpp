// The parametric wave curve beyond a = b1/2 (the "periodic regime" of the seed's Fig. 5b):
// the zone reaches the |cos| branch of eq. 2, so the right-hand side of eq. 5 is
//   g(v) = E* H1 (m+1) v (1+v^2) / (1 + v^2 + m |1 - v^2|)^2,
// piecewise rational with a kink in its slope at v = +-1 (cos x^ = 0). The inversion is
// evaluated by adaptive Gauss-Kronrod quadrature split at the kinks, which converges
// geometrically on each smooth piece (MATH.md section 4). Normalised: b1 = pi, H1 = E* = 1;
// angles are passed as half-angle sines and cosines so that nothing cancels.
#pragma once

namespace wavecontact::detail {

// The zone in half-angles: s = sin(a^/2), c = cos(a^/2), a^ = pi a/b1 in (0, pi).
struct HalfAngles {
  double s, c;
};

// p^(x^) of eq. 12 for the zone `zone` at the point with half-angles `point`,
// 0 <= x^ < a^. D = cos x^ - cos a^ (computed without cancellation by the caller).
double periodic_pressure(double m, HalfAngles zone, HalfAngles point, double D);

// P^ = 2 sqrt2 Int_0^a^ G sin(x^/2)/sqrt(cos x^ - cos a^) dx^ (MATH.md fact 7, eq. 6), with
// sin(x^/2) = s sin(phi):  P^ = 4 (m+1) s^2 Int_0^{pi/2} sin^2(phi) / (1 + m |cos x^|)^2 dphi.
double periodic_load(double m, double s);

// dP^/ds, the same integral differentiated under the sign:
// 8 (m+1) s Int_0^{pi/2} sin^2(phi) N(cos x^) / (1 + m |cos x^|)^3 dphi,
// N(c) = 1 + 2m - m c for c >= 0 and 1 - 2m + m c for c < 0.
double periodic_load_slope(double m, double s);

}  // namespace wavecontact::detail
