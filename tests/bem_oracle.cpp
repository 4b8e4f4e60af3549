#include "bem_oracle.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>
#include <fftw3.h>

#include <boost/math/constants/constants.hpp>

namespace wavecontact::test {

namespace {

using boost::math::double_constants::pi;

// u = K p on the periodic grid: u_k = 2 p_k/(E |k|), the mean of u left at 0.
class Influence {
 public:
  Influence(int M, double E) : M_(M), E_(E), real_(M), spectrum_(M / 2 + 1) {
    auto* c = reinterpret_cast<fftw_complex*>(spectrum_.data());
    forward_ = fftw_plan_dft_r2c_1d(M, real_.data(), c, FFTW_ESTIMATE);
    backward_ = fftw_plan_dft_c2r_1d(M, c, real_.data(), FFTW_ESTIMATE);
  }
  ~Influence() {
    fftw_destroy_plan(forward_);
    fftw_destroy_plan(backward_);
  }
  Influence(const Influence&) = delete;
  Influence& operator=(const Influence&) = delete;

  void apply(const std::vector<double>& p, std::vector<double>& u) {
    std::copy(p.begin(), p.end(), real_.begin());
    fftw_execute(forward_);
    spectrum_[0] = 0;
    for (int k = 1; k <= M_ / 2; ++k) spectrum_[k] *= 2.0 / (E_ * k) / M_;
    fftw_execute(backward_);
    u = real_;
  }

 private:
  int M_;
  double E_;
  std::vector<double> real_;
  std::vector<std::complex<double>> spectrum_;
  fftw_plan forward_, backward_;
};

// The zone end next to the contact point j (the last one, towards direction +-1): p^2 is a
// smooth function of x up to the end (p ~ sqrt(e - x)), and the discrete pressure is accurate
// away from it, so a least-squares polynomial of degree 4 through the points 5 to 40 in from
// j, extrapolated to its root. The window stays inside the zone and off the profile's kinks
// (where p has an s log s term); in a zone too short for it, the gap g >= 0 beyond j, which
// grows like (x - e)^(3/2), from the second and third points out.
double edge(const std::vector<double>& p, const std::vector<double>& g, int j, int direction, double h, int inner_limit,
            const std::vector<double>& kinks) {
  const int M = static_cast<int>(p.size());
  int far = 40;
  for (double k : kinks) {
    const double steps = direction * (h * j - k) / h;  // points from the kink to j, inwards
    if (steps > 0) far = std::min(far, static_cast<int>(steps) - 1);
  }
  far = std::min(far, std::abs(j - inner_limit));
  if (far >= 15) {
    constexpr int near = 5, degree = 4;
    Eigen::MatrixXd A(far - near + 1, degree + 1);
    Eigen::VectorXd b(far - near + 1);
    for (int k = near; k <= far; ++k) {
      const double t = -k, value = p[(j - direction * k + M) % M];
      for (int q = 0; q <= degree; ++q) A(k - near, q) = std::pow(t, q);
      b[k - near] = value * value;
    }
    const Eigen::VectorXd c = A.colPivHouseholderQr().solve(b);
    double t = 0.5;  // Newton from half a step out
    for (int iteration = 0; iteration < 50; ++iteration) {
      double v = 0, dv = 0;
      for (int q = degree; q >= 0; --q) v = v * t + c[q];
      for (int q = degree; q >= 1; --q) dv = dv * t + q * c[q];
      t -= v / dv;
    }
    if (std::isfinite(t) && t > -1 && t < 2) return h * (j + direction * t);
  }
  auto root = [&](int i) { return std::cbrt(std::pow(std::max(g[(i + M) % M], 0.0), 2)); };
  const int k = j + 2 * direction;
  const double g1 = root(k), g2 = root(k + direction);
  const double step = g2 > g1 ? g1 / (g2 - g1) : 1.5;
  return h * (k - direction * std::min(step, 1.5));
}

}  // namespace

BemContact bem_contact(const std::function<double(double)>& y, double E, double P, int M,
                       const std::vector<double>& kinks) {
  if (M < 16 || M % 2 != 0) throw std::invalid_argument("bem_contact: M must be even, >= 16");
  const double h = 2 * pi / M, mean = P / (2 * pi);
  std::vector<double> height(M);
  double top = -1e300;
  for (int i = 0; i < M; ++i) height[i] = y(h * i), top = std::max(top, height[i]);
  std::vector<double> h0(M);
  for (int i = 0; i < M; ++i) h0[i] = top - height[i];

  Influence K(M, E);
  std::vector<double> p(M, mean), u(M), g(M), t(M, 0.0), r(M), previous(M);
  double G_old = 1;
  bool conjugate = false;
  int iteration = 0;
  for (; iteration < 200000; ++iteration) {
    K.apply(p, u);
    double g_mean = 0;
    int active = 0;
    for (int i = 0; i < M; ++i) {
      g[i] = u[i] + h0[i];
      if (p[i] > 0) g_mean += g[i], ++active;
    }
    g_mean /= active;
    double G = 0;
    for (int i = 0; i < M; ++i) {
      g[i] -= g_mean;
      if (p[i] > 0) G += g[i] * g[i];
    }
    for (int i = 0; i < M; ++i) t[i] = p[i] > 0 ? g[i] + (conjugate ? G / G_old * t[i] : 0) : 0;
    G_old = G;
    K.apply(t, r);
    double r_mean = 0;
    for (int i = 0; i < M; ++i)
      if (p[i] > 0) r_mean += r[i];
    r_mean /= active;
    double gt = 0, rt = 0;
    for (int i = 0; i < M; ++i) {
      if (p[i] > 0) gt += g[i] * t[i], rt += (r[i] - r_mean) * t[i];
    }
    const double tau = rt != 0 ? gt / rt : 0;
    previous = p;
    for (int i = 0; i < M; ++i) {
      if (p[i] > 0) p[i] = std::max(0.0, p[i] - tau * t[i]);
    }
    bool overlap = false;
    for (int i = 0; i < M; ++i) {
      if (p[i] == 0 && g[i] < 0) {
        p[i] -= tau * g[i];
        overlap = true;
      }
    }
    conjugate = !overlap;
    double sum = 0;
    for (double v : p) sum += v;
    const double scale = mean * M / sum;
    double change = 0, total = 0;
    for (int i = 0; i < M; ++i) {
      p[i] *= scale;
      change += std::fabs(p[i] - previous[i]);
      total += p[i];
    }
    if (change < 1e-14 * total && iteration > 2) break;
  }

  BemContact c{};
  c.iterations = iteration;
  // The gap, 0 on the contact.
  K.apply(p, u);
  double approach = 0;
  int active = 0;
  for (int i = 0; i < M; ++i) {
    if (p[i] > 0) approach += u[i] + h0[i], ++active;
  }
  approach /= active;
  for (int i = 0; i < M; ++i) g[i] = u[i] + h0[i] - approach;
  // Zones of [0, pi]: points 0..M/2 (the profile and the pressure are even).
  const int half = M / 2;
  for (int i = 0; i <= half; ++i) {
    if (!(p[i] > 0)) continue;
    int j = i;
    while (j + 1 <= half && p[j + 1] > 0) ++j;
    const double lo = i == 0 ? 0 : edge(p, g, i, -1, h, j, kinks);
    const double hi = j == half ? pi : edge(p, g, j, +1, h, i == 0 ? -j : i, kinks);
    c.zone_ends.push_back(lo);
    c.zone_ends.push_back(hi);
    c.contact_fraction += (hi - lo) / pi;
    i = j;
  }
  c.p0 = p[0];
  // The largest grid value, and the vertex of the parabola through it and its neighbours
  // (mirrored at 0 and pi) where that parabola is concave: a smooth peak; the pressure can
  // also peak in a cusp (at a kink of the profile), where the grid value is the estimate.
  int best = 0;
  for (int i = 0; i <= half; ++i)
    if (p[i] > p[best]) best = i;
  const double left = p[(best - 1 + M) % M], right = p[(best + 1) % M], mid = p[best];
  const double curvature = left - 2 * mid + right;
  c.max_pressure = mid;
  if (curvature < 0) c.max_pressure = mid - 0.125 * (left - right) * (left - right) / curvature;
  c.grid_max_pressure = mid;
  return c;
}

namespace {

// Richardson extrapolation of a quantity that converges like a power of the spacing (values
// on grids M, 2M, 4M): the observed order where the differences shrink, else the finest value;
// the error estimate is the last correction, or the last difference.
std::pair<double, double> extrapolate(double q1, double q2, double q4) {
  const double d1 = q2 - q1, d2 = q4 - q2;
  if (d2 == 0) return {q4, std::fabs(d1) / 4};
  const double ratio = d1 / d2;
  if (ratio > 1.5) {
    const double correction = d2 / (ratio - 1);
    return {q4 + correction, std::fabs(correction)};
  }
  return {q4, std::max(std::fabs(d1), std::fabs(d2))};
}

// A quantity whose error changes sign from grid to grid (zone ends): the finest value, and
// the spread of the three, at least a fiftieth of the finest spacing, as its error.
std::pair<double, double> spread(double q1, double q2, double q4, double resolution) {
  return {q4, std::max({std::fabs(q1 - q4), std::fabs(q2 - q4), std::fabs(q1 - q2), resolution})};
}

}  // namespace

BemEstimate bem_extrapolated(const std::function<double(double)>& y, double E, double P, int M,
                             const std::vector<double>& kinks) {
  const BemContact a = bem_contact(y, E, P, M, kinks), b = bem_contact(y, E, P, 2 * M, kinks),
                   c = bem_contact(y, E, P, 4 * M, kinks);
  if (a.zone_ends.size() != b.zone_ends.size() || b.zone_ends.size() != c.zone_ends.size()) {
    throw std::runtime_error("bem_extrapolated: the grids find " + std::to_string(a.zone_ends.size() / 2) + ", " +
                             std::to_string(b.zone_ends.size() / 2) + " and " + std::to_string(c.zone_ends.size() / 2) +
                             " zones");
  }
  BemEstimate e{};
  const double resolution = 2 * pi / (4 * M) / 50;
  for (std::size_t i = 0; i < c.zone_ends.size(); ++i) {
    const auto [v, err] = spread(a.zone_ends[i], b.zone_ends[i], c.zone_ends[i], resolution);
    e.zone_ends.push_back(v);
    e.zone_ends_error.push_back(err);
  }
  std::tie(e.contact_fraction, e.contact_fraction_error) =
      spread(a.contact_fraction, b.contact_fraction, c.contact_fraction, resolution / pi);
  std::tie(e.p0, e.p0_error) = extrapolate(a.p0, b.p0, c.p0);
  std::tie(e.max_pressure, e.max_pressure_error) = extrapolate(a.max_pressure, b.max_pressure, c.max_pressure);
  // The vertex correction itself is part of the uncertainty (a cusp has no vertex).
  e.max_pressure_error += std::fabs(c.max_pressure - c.grid_max_pressure);
  return e;
}

}  // namespace wavecontact::test
