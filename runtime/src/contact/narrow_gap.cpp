#include "narrow_gap.hpp"

#include <algorithm>
#include <cmath>

namespace wavecontact::detail {

bool NarrowGap::inside(double x) const { return std::fabs(x - centre) < half; }

double NarrowGap::correction(double x) const {
  // With s = sqrt(1 - half^2 / w^2), Q R - (A w^3 + B w^2 + E1 w + E0) is
  // (A w^3 + B w^2 + D w)(s - 1) + A half^2 w / 2 + B half^2 / 2 by the matching
  // (D - E1 = A half^2 / 2, E0 = -B half^2 / 2), and s - 1 = -(half^2 / w^2) / (1 + s).
  const double w = x - centre, c2 = half * half, s = std::sqrt(std::max(0.0, 1 - c2 / (w * w)));
  return c2 * c2 * (A / (4 * w * (1 + s)) - (A * w + B) / (2 * w * w * (1 + s) * (1 + s)));
}

double NarrowGap::gap(double x, double E) const {
  // int_w^half t^k sqrt(half^2 - t^2) dt for k = 0, 1, 2.
  const double c = half, w = std::clamp(x - centre, -c, c), root = std::sqrt((c - w) * (c + w));
  const double angle = std::acos(w / c);
  const double i0 = (c * c * angle - w * root) / 2;
  const double i1 = root * root * root / 3;
  const double i2 = (c * c * c * c * angle - w * (2 * w * w - c * c) * root) / 8;
  return 2 / E * (A * i2 + B * i1 + D * i0);
}

double NarrowGap::error(double room) const {
  const double c4 = half * half * half * half;
  return std::fabs(mu) * c4 + kappa * c4 / (room * room);
}

std::optional<NarrowGap> narrow_gap(const std::function<double(double)>& p, double x, double step) {
  const double h = step;
  // The minimum: Newton's method on the differences, the slope's of fourth order (a second
  // order's would leave it lambda h^2 / (6 kappa) off, a slope of the cubic that the inner
  // solution does not match).
  for (int i = 0; i < 50; ++i) {
    const double left = p(x - h), middle = p(x), right = p(x + h);
    const double slope = (8 * (right - left) - (p(x + 2 * h) - p(x - 2 * h))) / (12 * h);
    const double curvature = (right - 2 * middle + left) / (h * h);
    if (!(curvature > 0)) return std::nullopt;
    const double move = std::clamp(-slope / curvature, -10 * h, 10 * h);
    x += move;
    if (std::fabs(move) < 1e-6 * h) break;
  }
  NarrowGap g;
  g.x0 = x;
  const double p0 = p(x), p1 = p(x + h), m1 = p(x - h), p2 = p(x + 2 * h), m2 = p(x - 2 * h);
  g.T = -p0;
  g.kappa = (p1 - 2 * p0 + m1) / (h * h);
  g.lambda = (p2 - 2 * p1 + 2 * m1 - m2) / (2 * h * h * h);
  g.mu = (p2 - 4 * p1 + 6 * p0 - 4 * m1 + m2) / (h * h * h * h);
  if (!(g.T > 0 && g.kappa > 0)) return std::nullopt;
  // The matching of Q R to the cubic, sigma = centre - x0:
  //   A = lambda/6, B = kappa/2 + lambda sigma/2, D = -A half^2/4 (no load of its own),
  //   kappa sigma + lambda sigma^2/2 = -3 A half^2/4, B half^2/2 = T - kappa sigma^2/2 - lambda sigma^3/6,
  // by fixed-point steps from the parabola's sigma = 0, half = 2 sqrt(T/kappa).
  g.A = g.lambda / 6;
  double sigma = 0, c = 2 * std::sqrt(g.T / g.kappa);
  for (int i = 0; i < 20; ++i) {
    sigma = -(0.75 * g.A * c * c + g.lambda * sigma * sigma / 2) / g.kappa;
    g.B = g.kappa / 2 + g.lambda * sigma / 2;
    c = std::sqrt(2 * (g.T - g.kappa * sigma * sigma / 2 - g.lambda * sigma * sigma * sigma / 6) / g.B);
  }
  g.D = -g.A * c * c / 4;
  g.centre = x + sigma, g.half = c;
  if (!(g.half > 0 && g.B > 0)) return std::nullopt;
  return g;
}

}  // namespace wavecontact::detail
