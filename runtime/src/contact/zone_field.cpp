#include "zone_field.hpp"

#include <cmath>

#include "chebyshev.hpp"

namespace wavecontact::detail {

namespace {

// zeta, log|zeta| and w = sgn(z) sqrt(z^2 - 1) at the point off the zone.
struct Conformal {
  double zeta, log_zeta, w;
};

Conformal conformal(const ZoneGeometry& g, const HalfAngle& x) {
  const double zm = g.z_minus_1(x), zp = g.z_plus_1(x);
  const double root = std::sqrt(zm * zp);  // both of one sign off the zone
  if (zm > 0) {                            // z > 1
    const double sum = 1 + zm + root;      // z + w
    return {1 / sum, -std::log1p(zm + root), root};
  }
  const double sum = 1 - zp + root;  // -(z + w) = |z| + |w|, |z| = 1 - zp
  return {-1 / sum, -std::log1p(-zp + root), -root};
}

}  // namespace

double self_logarithm(const ZoneGeometry& g) { return std::log(2 / g.h); }

FieldValue far_field(const ZoneGeometry& g, const double* d, int count, const HalfAngle& x) {
  const Conformal c = conformal(g, x);
  double series = 0, sum = d[0], power = 1;
  for (int j = 1; j < count; ++j) {
    power *= c.zeta;
    const double term = d[j] * power;
    series += term / j, sum += term;
    if (std::fabs(power) < 1e-17) break;
  }
  return {g.h * (d[0] * (self_logarithm(g) + c.log_zeta) + series), -sum / c.w};
}

double far_potential(const ZoneGeometry& g, const double* d, int count, const HalfAngle& x) {
  const Conformal c = conformal(g, x);
  double series = 0, power = 1;
  for (int j = 1; j < count; ++j) {
    power *= c.zeta;
    series += d[j] * power / j;
    if (std::fabs(power) < 1e-17) break;
  }
  return g.h * (d[0] * (self_logarithm(g) + c.log_zeta) + series);
}

void own_potential(const ZoneGeometry& g, const double* d, int count, double* o) {
  o[0] = g.h * self_logarithm(g) * d[0];
  for (int j = 1; j < count; ++j) o[j] = g.h * d[j] / j;
}

double zone_pressure(const ZoneGeometry& g, const double* d, int count, double x) {
  const HalfAngle p = HalfAngle::of(x);
  const double one_minus = -g.z_minus_1(p), one_plus = g.z_plus_1(p);  // 1 - tau, 1 + tau
  const double tau = (one_plus - one_minus) / 2;
  if (g.top() && g.valley()) return chebyshev::sum_t(d, static_cast<std::size_t>(count), std::cos(x));
  std::vector<double> c(static_cast<std::size_t>(count), 0.0);
  if (g.top()) {
    // sum d_j T_j = (1 + tau) sum g_j V_j, (1 + tau) V_j = T_j + T_{j+1}: d_k = g_k + g_{k-1};
    // sin x / sqrt(1 - tau) = sqrt(2 h) cos(x/2).
    for (int k = 0; k + 1 < count; ++k)
      c[static_cast<std::size_t>(k)] = d[k] - (k > 0 ? c[static_cast<std::size_t>(k - 1)] : 0);
    return std::sqrt(2 * g.h) * p.cos_half * std::sqrt(one_plus) *
           chebyshev::sum_v(c.data(), static_cast<std::size_t>(count - 1), tau);
  }
  if (g.valley()) {
    // (1 - tau) W_j = T_j - T_{j+1}: d_k = g_k - g_{k-1}; sin x / sqrt(1 + tau) = sqrt(2 h) sin(x/2).
    for (int k = 0; k + 1 < count; ++k)
      c[static_cast<std::size_t>(k)] = d[k] + (k > 0 ? c[static_cast<std::size_t>(k - 1)] : 0);
    return std::sqrt(2 * g.h) * p.sin_half * std::sqrt(one_minus) *
           chebyshev::sum_w(c.data(), static_cast<std::size_t>(count - 1), tau);
  }
  // (1 - tau^2) U_j = (T_j - T_{j+2}) / 2: d_k = (c_k - c_{k-2}) / 2.
  for (int k = 0; k + 2 < count; ++k) {
    c[static_cast<std::size_t>(k)] = 2 * d[k] + (k >= 2 ? c[static_cast<std::size_t>(k - 2)] : 0);
  }
  return std::sin(x) * std::sqrt(one_minus * one_plus) *
         chebyshev::sum_u(c.data(), static_cast<std::size_t>(count - 2), tau);
}

}  // namespace wavecontact::detail
