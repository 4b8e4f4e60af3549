#include "zone.hpp"

#include <algorithm>
#include <cmath>

#include "constants.hpp"

namespace wavecontact::detail {

double cos_difference(double x, double y) { return -2 * std::sin((x + y) / 2) * std::sin((x - y) / 2); }

HalfAngle HalfAngle::of(double x) { return {x, std::sin(x / 2), std::cos(x / 2)}; }

ZoneGeometry::ZoneGeometry(double a_, double b_) : a(a_), b(b_), end_a(HalfAngle::of(a_)), end_b(HalfAngle::of(b_)) {
  h = std::sin((a + b) / 2) * std::sin((b - a) / 2);
  m = std::cos((a + b) / 2) * std::cos((b - a) / 2);
}

bool ZoneGeometry::valley() const { return b == pi; }

namespace {

// cos x - cos y = -2 sin((x + y)/2) sin((x - y)/2), for x, y in [0, pi].
double cos_difference(const HalfAngle& x, const HalfAngle& y) {
  const double sum = x.sin_half * y.cos_half + x.cos_half * y.sin_half;
  return -2 * sum * std::sin((x.x - y.x) / 2);
}

}  // namespace

double ZoneGeometry::z_minus_1(const HalfAngle& p) const {
  return (top() ? -2 * p.sin_half * p.sin_half : cos_difference(p, end_a)) / h;
}
double ZoneGeometry::z_plus_1(const HalfAngle& p) const {
  return (valley() ? 2 * p.cos_half * p.cos_half : cos_difference(p, end_b)) / h;
}

std::vector<double> ZoneGeometry::angles_of(const std::vector<double>& tau) const {
  // 1 - s = 2 sin^2(a/2) + h (1 - tau) near the top, 1 + s = 2 cos^2(b/2) + h (1 + tau) near
  // the valley: sums of non-negative terms.
  std::vector<double> x(tau.size());
  const double sa = std::sin(a / 2), cb = std::cos(b / 2);
  for (std::size_t i = 0; i < tau.size(); ++i) {
    const double s = m + h * tau[i];
    if (s >= 0) {
      const double one_minus = 2 * sa * sa + h * (1 - tau[i]);
      x[i] = 2 * std::asin(std::min(1.0, std::sqrt(one_minus / 2)));
    } else {
      const double one_plus = 2 * cb * cb + h * (1 + tau[i]);
      x[i] = pi - 2 * std::asin(std::min(1.0, std::sqrt(one_plus / 2)));
    }
    x[i] = std::clamp(x[i], a, b);
  }
  return x;
}

double ZoneGeometry::dh_da() const { return -std::sin(a) / 2; }
double ZoneGeometry::dh_db() const { return std::sin(b) / 2; }
double ZoneGeometry::dm_da() const { return -std::sin(a) / 2; }
double ZoneGeometry::dm_db() const { return -std::sin(b) / 2; }

}  // namespace wavecontact::detail
