// Integrals whose integrand is smooth inside (a, b) but for logarithmic singularities at a and
// b or next to them: a kink correction's potential at a point (its kink, the point and the
// window's edges cut the window into such stretches) and its moments (kink_correction.cpp).
//
// Gauss-Legendre in w after Kress's sigmoidal substitution t = a + (b - a) v(w),
// v = w^5 / (w^5 + (1 - w)^5), under which such an integrand vanishes like w^4 log w at the
// ends. v is steep at w = 1/2 (its complex poles lie near it), so w's interval is cut into six
// panels of 30 points: 180 fixed points, no adaptation. Its error, in eps of Int |f|
// (tests/log_end_quadrature_test.cpp): up to 12.3 with a logarithm at an end times a
// polynomial up to degree 24, 19.9 up to degree 48 (the window's); up to 2.3 with one a
// distance d beyond an end, d from the stretch's length down to 1e-7 of it, but up to 105 from
// 1e-8 to 1e-13 (the windows take d down to about 3e-7). On the wave curve's windows (m = 0.2
// to 32.8) the potentials and the moments lie within 4.1e-15 of Int |f| from the rule on 40
// panels, as tanh-sinh's at a tolerance of 1e-15 did, which they were computed by before: a
// map over 40 shapes took 3.2 s instead of 8.0 s, where the windows had taken 64 %
// (2026-11-29). With the window of order 20 (degree 48), against the 40 panels at m = 0.2 to
// 32.8, radii 0.01 and more, 81 points across 2.2 r: potentials within 2.4e-14 of Int |f|
// (1.5e-14 with order 8 by the same check), moments to the 16th within 1.4e-14, higher ones
// (weighed by 2^-k in the far field) within 1.0e-13; narrower windows carry their slope
// jump's noise, up to 6.6e-12 (3.1e-12 with order 8, which those below 3e-4 keep).
//
// f is also called at a or b where a point rounds onto it (its weight below 2e-17): it must be
// finite there (0 for a singular point).
#pragma once

#include <vector>

namespace wavecontact::detail {

struct LogEndNode {
  double fraction, complement, weight;  // v(w), 1 - v(w) without cancellation, and v'(w) w_i
};

// The 180 nodes on [0, 1], computed once.
const std::vector<LogEndNode>& log_end_nodes();

// Int_a^b f (0 unless b > a). Each point is taken from its nearer end, so that a point next to
// b keeps its distance from b.
template <class F>
double log_end_integral(const F& f, double a, double b) {
  if (!(b > a)) return 0.0;
  const double length = b - a;
  double sum = 0;
  for (const LogEndNode& n : log_end_nodes()) {
    sum += n.weight * f(n.fraction < 0.5 ? a + length * n.fraction : b - length * n.complement);
  }
  return sum * length;
}

}  // namespace wavecontact::detail
