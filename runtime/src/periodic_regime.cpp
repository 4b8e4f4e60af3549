#include "periodic_regime.hpp"

#include <cmath>

namespace wavecontact::detail {

namespace {

// g(v) of eq. 5 for the curve of eq. 2 (normalised) on one branch: (m+1) N(v)/q(v)^2 with
// N = v (1 + v^2) and q = c0 + c1 v^2, the top (|v| <= 1, cos x^ >= 0: c0 = 1 + m,
// c1 = 1 - m) or the flank (c0 = 1 - m, c1 = 1 + m), each continued off its own side.
struct Branch {
  double m, c0, c1;

  double q(double v) const { return c0 + c1 * v * v; }
  double g(double v) const {
    const double qv = q(v);
    return (m + 1) * v * (1 + v * v) / (qv * qv);
  }
  // (g(v) - g(u))/(v - u) with the factor v - u divided out of the numerator: no digits lost
  // as v -> u. N(v) q(u)^2 - N(u) q(v)^2 = (v - u) [q(u)^2 (v^2 + uv + u^2 + 1)
  // - N(u) c1 (v + u)(q(v) + q(u))].
  double divided_difference(double v, double u) const {
    const double qv = q(v), qu = q(u);
    const double numerator = qu * qu * (v * v + u * v + u * u + 1) - u * (1 + u * u) * c1 * (v + u) * (qv + qu);
    return (m + 1) * numerator / (qv * qv * qu * qu);
  }
};

}  // namespace

double periodic_pressure(double m, HalfAngles zone, HalfAngles point, double D) {
  const Branch top{m, 1 + m, 1 - m}, flank{m, 1 - m, 1 + m};
  const PiecewiseDividedDifference divided_difference{
      1,
      [&](double v) { return top.g(v); },
      [&](double v) { return flank.g(v); },
      [&](double v, double u) { return top.divided_difference(v, u); },
      [&](double v, double u) { return flank.divided_difference(v, u); },
      // (m+1) N(u) (q_top^2 - q_flank^2)/(q_top q_flank)^2, q_top - q_flank = 2m (1 - u^2)
      // without cancellation.
      [&](double u) {
        const double qt = top.q(u), qf = flank.q(u), a = std::fabs(u);
        return (m + 1) * u * (1 + u * u) * 2 * m * (1 - a) * (1 + a) * (qt + qf) / (qt * qt * qf * qf);
      }};
  return kinked_pressure(divided_difference, 1, zone, point, D);
}

}  // namespace wavecontact::detail
