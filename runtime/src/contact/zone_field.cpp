#include "zone_field.hpp"

#include <algorithm>
#include <cmath>

#include "chebyshev.hpp"

namespace wavecontact::detail {

namespace {

// zeta, log|zeta|, w = sgn(z) sqrt(z^2 - 1) and z at the point off the zone.
struct Conformal {
  double zeta, log_zeta, w, z;
};

Conformal conformal(const ZoneGeometry& g, const HalfAngle& x) {
  const double zm = g.z_minus_1(x), zp = g.z_plus_1(x);
  const double root = std::sqrt(zm * zp);  // both of one sign off the zone
  if (zm > 0) {                            // z > 1
    const double sum = 1 + zm + root;      // z + w
    return {1 / sum, -std::log1p(zm + root), root, 1 + zm};
  }
  const double sum = 1 - zp + root;  // -(z + w) = |z| + |w|, |z| = 1 - zp
  return {-1 / sum, -std::log1p(-zp + root), -root, zp - 1};
}

}  // namespace

double self_logarithm(const ZoneGeometry& g) { return std::log(2 / g.h); }

namespace {

// Eight points side by side, one vector (GCC's vector extension: whatever registers the
// target has), and a lane's mask.
using Lanes = double __attribute__((vector_size(64)));
using LaneMask = long __attribute__((vector_size(64)));
constexpr std::size_t lanes = sizeof(Lanes) / sizeof(double);

}  // namespace

// Each lane's series runs as the point's own would alone (its power frozen and its sums kept
// once its terms fall below 1e-17), so that every point gets the bits of the scalar sum; a
// last partial block repeats its last point's map. Cloned for AVX2 and AVX-512; zone_field.cpp is
// compiled without contracting products and sums into FMAs, so every CPU gives the same bits.
__attribute__((target_clones("avx512f", "avx2", "default"))) void far_fields(const ZoneGeometry& g, const double* d,
                                                                             int count, const HalfAngle* x,
                                                                             std::size_t points, FieldValue* out) {
  const double self = self_logarithm(g);
  for (std::size_t first = 0; first < points; first += lanes) {
    const std::size_t n = std::min(lanes, points - first);
    Lanes zeta, log_zeta, w;
    for (std::size_t i = 0; i < lanes; ++i) {
      const Conformal c = i < n ? conformal(g, x[first + i]) : Conformal{zeta[n - 1], log_zeta[n - 1], w[n - 1], 0};
      zeta[i] = c.zeta, log_zeta[i] = c.log_zeta, w[i] = c.w;
    }
    Lanes series = {}, sum = Lanes{} + d[0], power = Lanes{} + 1.0;
    LaneMask active = LaneMask{} == 0;  // every lane
    for (int j = 1; j < count; ++j) {
      power = active ? power * zeta : power;
      const Lanes term = d[j] * power;
      series = active ? series + term / static_cast<double>(j) : series;
      sum = active ? sum + term : sum;
      const Lanes size = power < 0 ? -power : power;
      active &= ~(size < 1e-17);
      bool any = false;
      for (std::size_t i = 0; i < lanes; ++i) any |= active[i] != 0;
      if (!any) break;
    }
    for (std::size_t i = 0; i < n; ++i) {
      out[first + i] = {g.h * (d[0] * (self + log_zeta[i]) + series[i]), -sum[i] / w[i]};
    }
  }
}

// As far_fields, each lane's series running as its point's would alone. With sum = |z| + |w| =
// 1/|zeta|: sum_i - sum_ref = +-dz + (z_i^2 - z_ref^2)/(|w_i| + |w_ref|), dz = (s_i - s_ref)/h;
// zeta_i - zeta_ref = -+(sum_i - sum_ref)/(sum_i sum_ref); log|zeta_i| - log|zeta_ref| =
// -log1p((sum_i - sum_ref)/sum_ref); and sum_j (d_j/j)(zeta_i^j - zeta_ref^j) = (zeta_i -
// zeta_ref) sum_j (d_j/j) E_j, E_1 = 1, E_{j+1} = zeta_i E_j + zeta_ref^j. A lane stops once
// j max(|zeta_i|, |zeta_ref|)^j falls below 1e-17.
__attribute__((target_clones("avx512f", "avx2", "default"))) void far_field_differences(
    const ZoneGeometry& g, const double* d, int count, const HalfAngle& reference, const HalfAngle* x,
    const double* from_reference, std::size_t points, FieldValue* out) {
  const Conformal r = conformal(g, reference);
  const bool above = r.zeta > 0;  // the points beyond the zone's end at x^ = a (z > 1)
  const double sign = above ? 1 : -1;
  const double sum_r = 1 / std::fabs(r.zeta), w_r = std::fabs(r.w);
  for (std::size_t first = 0; first < points; first += lanes) {
    const std::size_t n = std::min(lanes, points - first);
    Lanes zeta, w, dsum, largest;
    for (std::size_t i = 0; i < lanes; ++i) {
      const std::size_t at = first + std::min(i, n - 1);
      const Conformal c = conformal(g, x[at]);
      const double dz = from_reference[at] / g.h;
      zeta[i] = c.zeta, w[i] = c.w;
      dsum[i] = sign * dz + dz * (c.z + r.z) / (std::fabs(c.w) + w_r);
      largest[i] = std::max(std::fabs(c.zeta), std::fabs(r.zeta));
    }
    Lanes series = {}, sum = Lanes{} + d[0], power = Lanes{} + 1.0, E = Lanes{} + 1.0, size = Lanes{} + 1.0;
    double reference_power = 1;  // zeta_ref^(j-1)
    LaneMask active = LaneMask{} == 0;
    for (int j = 1; j < count; ++j) {
      power = active ? power * zeta : power;
      series = active ? series + (d[j] / static_cast<double>(j)) * E : series;
      sum = active ? sum + d[j] * power : sum;
      reference_power *= r.zeta;
      E = active ? zeta * E + reference_power : E;
      size = active ? size * largest : size;
      active &= ~(static_cast<double>(j) * size < 1e-17);
      bool any = false;
      for (std::size_t i = 0; i < lanes; ++i) any |= active[i] != 0;
      if (!any) break;
    }
    for (std::size_t i = 0; i < n; ++i) {
      const double sum_i = 1 / std::fabs(zeta[i]);
      const double zeta_difference = -sign * dsum[i] / (sum_i * sum_r);
      out[first + i] = {g.h * (-d[0] * std::log1p(dsum[i] / sum_r) + zeta_difference * series[i]), -sum[i] / w[i]};
    }
  }
}

double far_potential(const ZoneGeometry& g, const double* d, int count, const HalfAngle& x) {
  FieldValue field;
  far_fields(g, d, count, &x, 1, &field);
  return field.potential;
}

void own_potential(const ZoneGeometry& g, const double* d, int count, double* o) {
  o[0] = g.h * self_logarithm(g) * d[0];
  for (int j = 1; j < count; ++j) o[j] = g.h * d[j] / j;
}

std::vector<double> bounded_pressure_series(const ZoneGeometry& g, const double* d, int count) {
  if (g.top() && g.valley()) return std::vector<double>(d, d + count);
  std::vector<double> c(static_cast<std::size_t>(count - (g.top() || g.valley() ? 1 : 2)), 0.0);
  if (g.top()) {
    // sum d_j T_j = (1 + tau) sum g_j V_j, (1 + tau) V_j = T_j + T_{j+1}: d_k = g_k + g_{k-1}.
    for (std::size_t k = 0; k < c.size(); ++k) c[k] = d[k] - (k > 0 ? c[k - 1] : 0);
  } else if (g.valley()) {
    // (1 - tau) W_j = T_j - T_{j+1}: d_k = g_k - g_{k-1}.
    for (std::size_t k = 0; k < c.size(); ++k) c[k] = d[k] + (k > 0 ? c[k - 1] : 0);
  } else {
    // (1 - tau^2) U_j = (T_j - T_{j+2}) / 2: d_k = (c_k - c_{k-2}) / 2.
    for (std::size_t k = 0; k < c.size(); ++k) c[k] = 2 * d[k] + (k >= 2 ? c[k - 2] : 0);
  }
  return c;
}

void zone_pressures(const ZoneGeometry& g, const std::vector<double>& series, const double* x, double* p,
                    std::size_t points) {
  // p = factor * sum_j c_j P_j(tau), P = V at the top, W at the valley, U between;
  // sin x / sqrt(1 - tau) = sqrt(2 h) cos(x/2), sin x / sqrt(1 + tau) = sqrt(2 h) sin(x/2).
  // In chunks whose tau and factors stay on the stack (a single point allocates nothing).
  const bool full = g.top() && g.valley();
  const chebyshev::Kind kind = full         ? chebyshev::Kind::t
                               : g.top()    ? chebyshev::Kind::v
                               : g.valley() ? chebyshev::Kind::w
                                            : chebyshev::Kind::u;
  constexpr std::size_t chunk = 64;
  for (std::size_t first = 0; first < points; first += chunk) {
    const std::size_t count = std::min(chunk, points - first);
    double tau[chunk], factor[chunk];
    for (std::size_t i = 0; i < count; ++i) {
      const double xi = x[first + i];
      if (full) {
        tau[i] = std::cos(xi), factor[i] = 1;
        continue;
      }
      const HalfAngle h = HalfAngle::of(xi);
      const double one_minus = -g.z_minus_1(h), one_plus = g.z_plus_1(h);  // 1 - tau, 1 + tau
      tau[i] = (one_plus - one_minus) / 2;
      factor[i] = g.top()      ? std::sqrt(2 * g.h) * h.cos_half * std::sqrt(one_plus)
                  : g.valley() ? std::sqrt(2 * g.h) * h.sin_half * std::sqrt(one_minus)
                               : std::sin(xi) * std::sqrt(one_minus * one_plus);
    }
    chebyshev::sums(kind, series.data(), series.size(), tau, p + first, count);
    for (std::size_t i = 0; i < count; ++i) p[first + i] *= factor[i];
  }
}

}  // namespace wavecontact::detail
