// A gap too narrow for two zones of their own (docs/contact.md, *Narrow gaps*). Where a gap
// beside a long zone is about to close, the zone's series needs about 12 sqrt(width / gap)
// nodes for its neighbour's end, a branch point as near as the gap is wide, and Newton's
// method stalls before it has them (campaign seed 41, sweep 10). Merged into one zone, the
// contact instead has a small tension there: a minimum of the merged pressure
// -T + kappa xi^2 / 2 + lambda xi^3 / 6 (xi = x^ - x0). The gap is then the inner solution of
// that minimum, which the merged pressure matches away from it: outside the gap
// [centre - half, centre + half] the pressure is Q(w) R(w), w = x^ - centre,
// Q = A w^2 + B w + D, R = w sqrt(1 - half^2 / w^2); inside, 0, and the gap there
// (2/E*) int_w^half Q(t) sqrt(half^2 - t^2) dt. Matching Q R to the cubic at large w, with no
// load of its own (its 1/w term 0), fixes A, B, D, centre and half.
#pragma once

#include <functional>
#include <optional>

namespace wavecontact::detail {

struct NarrowGap {
  double x0 = 0, T = 0, kappa = 0, lambda = 0;  // the merged pressure's cubic about its minimum
  double mu = 0;                                // and its fourth derivative, for the error
  double centre = 0, half = 0;                  // the gap
  double A = 0, B = 0, D = 0;                   // Q

  bool inside(double x) const;
  // What the merged pressure takes on outside the gap to be the contact's, Q R less the cubic,
  // in a form free of their cancellation (it falls like half^4 / w^2).
  double correction(double x) const;
  // The gap inside (E: the reduced modulus, as the solution's gap).
  double gap(double x, double E) const;
  // The error of the inner solution in the pressure (p^): the next term of the merged
  // pressure over the gap, |mu| half^4, and the correction's effect on the rest of the zone,
  // whose nearest end is `room` away, kappa half^4 / room^2.
  double error(double room) const;
};

// The narrow gap of the merged pressure p (x^) about its minimum near x, its derivatives taken
// by differences of `step`: none where that minimum is not below 0 or p not convex there.
std::optional<NarrowGap> narrow_gap(const std::function<double(double)>& p, double x, double step);

}  // namespace wavecontact::detail
