#include "grid_seed.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "chebyshev.hpp"
#include "constants.hpp"
#include "cosine_transform.hpp"

namespace wavecontact::detail {

namespace {

constexpr int most_iterations = 4000;
// The pressure's relative change per iteration at the end. The grid errs by a cell anyway and
// Newton's method replaces its digits: the seed needs the contact set and a pressure near
// the grid's own. At 1e-9, the 102-zone case of bench/contact_bench.cpp took 215 iterations;
// at 1e-6, 129, with the same zones. At 1e-4 the bench's map took 10 % less CPU time, but
// the seeds' contact sets were too rough for the campaign (scripts/contact_campaign.sh, seed
// 1): 25 of the 192 sweeps it reached in 11 minutes stalled at the budget of 60 s, none at
// 1e-6.
constexpr double settled = 1e-6;
// The weighted fraction of the cells in contact from which the iteration is preconditioned by
// the stiffness. Below it, the compliance's spread over the cells in contact is small and the
// plain iteration is as fast; above it, the preconditioned one takes 1.5 to 7 times fewer
// iterations. Campaign seed 55's sweep 38 (m = 25.58, six harmonics up to n = 972, 812
// zones a period, 60 loads): the seeds took 27529 iterations and 14.1 s (one stopping at
// the budget of 4000) unpreconditioned; 14663 and 8.8 s from 0.2; 9.6 s from 0.1, 9.4 s from
// 0.3, 10.2 s preconditioned throughout. Seed 47's first 100 sweeps of 16 loads: 217964
// iterations in 1244 seeds, 93.5 s, against 135222 and 68.8 s, the same zones at every load.
constexpr double preconditioned_from = 0.2;

// An even operator diagonal in the Fourier basis, on a sequence held as its half period
// (cells 0 … N/2): each cosine's amplitude times factor(k). An even sequence's discrete
// Fourier transform is its DCT-I, which applied twice is N times the identity.
class FourierMultiplier {
 public:
  template <class Factor>
  FourierMultiplier(std::size_t points, Factor factor) : factor_(points) {
    const double cells = 2.0 * static_cast<double>(points - 1);
    for (std::size_t k = 0; k < points; ++k) factor_[k] = factor(static_cast<double>(k), cells);
  }
  void apply(const std::vector<double>& p, std::vector<double>& u) {
    CosineTransform& transform = planned_transform(factor_.size(), CosineTransform::Kind::dct1);
    std::vector<double>& x = transform.data();
    std::copy(p.begin(), p.end(), x.begin());
    transform.apply();
    for (std::size_t k = 0; k < factor_.size(); ++k) x[k] *= factor_[k];
    transform.apply();
    u = x;
  }

 private:
  std::vector<double> factor_;
};

// Polonsky and Keer's iteration: conjugate gradients on the cells in contact, the gap's mean
// there as the rigid approach, cells that penetrate brought back in, the load kept; where a
// fifth of the period or more is in contact, the gap preconditioned by the half-plane's
// stiffness (the compliance's inverse), which the compliance restricted to the cells in
// contact resembles the more the more of them there are. On the half period, a cell inside
// it stands for itself and its mirror image: weight 2 (the cells at 0 and at the half
// period, 1). Where a step leaves the cells in contact as they were (no
// cell let go, none brought back in: three iterations in four), the new pressure is the old
// one less the step along the direction, scaled, and so is its displacement: it is updated
// from the direction's response instead of transformed again. A conjugate direction that
// is not a descent direction (the cells in contact changed under it) gives way to the
// gap's own: campaign seed 54's sweep 87 (m = 0, n = 538 and 902 at P = 3.2093) took a
// step of 238 along one whose curvature was 0.019, released half the cells, and went
// uphill next, its load below 0 at the third iteration; the seed returned there had 270
// zones in half a period, about twice as wide as the contact's (478 zones a period), and
// no contact settled from it in the work budget of 60 s. Restarted, the seed settles in
// 1486 iterations and the load solves in 0.9 s.
std::vector<double> grid_pressure(const std::vector<double>& clearance, double E, double mean_pressure) {
  const std::size_t n = clearance.size();
  const auto weight = [n](std::size_t i) { return i == 0 || i + 1 == n ? 1.0 : 2.0; };
  const double cells = 2.0 * static_cast<double>(n - 1);
  // The displacement of the periodic half-plane, u_k = 2 p_k / (E* |k|), its mean left at 0;
  // and its inverse, the stiffness, whose mean (k = 0) is that of k = 1 (any will do: the
  // iteration takes the mean off on the cells in contact).
  FourierMultiplier compliance(n, [E](double k, double N) { return k == 0 ? 0.0 : 2.0 / (E * k * N); });
  FourierMultiplier stiffness(n, [E](double k, double N) { return E * std::max(k, 1.0) / (2 * N); });
  // z: the gap, preconditioned or not, that the direction follows.
  std::vector<double> p(n, mean_pressure), u(n), gap(n), direction(n, 0.0), response(n), before(n), z(n);
  bool preconditioned = false;
  double G_before = 1;
  bool conjugate = false, displaced = false;  // displaced: u is the displacement of p
  for (int iteration = 0; iteration < most_iterations; ++iteration) {
    if (!displaced) compliance.apply(p, u);
    double approach = 0, contact = 0;
    for (std::size_t i = 0; i < n; ++i) {
      gap[i] = clearance[i] + u[i];
      if (p[i] > 0) approach += weight(i) * gap[i], contact += weight(i);
    }
    approach /= contact;
    for (std::size_t i = 0; i < n; ++i) gap[i] -= approach;
    // The gap on the cells in contact and on those that penetrate; preconditioned, the
    // stiffness's response to it, its mean over the cells in contact taken off, and on a
    // penetrating cell only a pull (z < 0), which brings the cell back in. A change of mode
    // starts the conjugate directions afresh.
    if (contact >= preconditioned_from * cells) {
      if (!preconditioned) conjugate = false;
      preconditioned = true;
      for (std::size_t i = 0; i < n; ++i) response[i] = p[i] > 0 || gap[i] < 0 ? gap[i] : 0.0;
      stiffness.apply(response, z);
      double z_mean = 0;
      for (std::size_t i = 0; i < n; ++i) {
        if (p[i] > 0) z_mean += weight(i) * z[i];
      }
      z_mean /= contact;
      for (std::size_t i = 0; i < n; ++i) z[i] = p[i] > 0 ? z[i] - z_mean : gap[i] < 0 ? std::min(z[i], 0.0) : 0.0;
    } else {
      if (preconditioned) conjugate = false;
      preconditioned = false;
      for (std::size_t i = 0; i < n; ++i) z[i] = p[i] > 0 || gap[i] < 0 ? gap[i] : 0.0;
    }
    double G = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (p[i] > 0) G += weight(i) * gap[i] * z[i];
    }
    // The direction's response, and the gap along it and its curvature on the cells in contact.
    const auto measure = [&](double& along, double& curvature) {
      compliance.apply(direction, response);
      double response_mean = 0;
      for (std::size_t i = 0; i < n; ++i) {
        if (p[i] > 0) response_mean += weight(i) * response[i];
      }
      response_mean /= contact;
      along = 0, curvature = 0;
      for (std::size_t i = 0; i < n; ++i) {
        if (p[i] > 0) {
          along += weight(i) * gap[i] * direction[i];
          curvature += weight(i) * (response[i] - response_mean) * direction[i];
        }
      }
    };
    for (std::size_t i = 0; i < n; ++i) {
      direction[i] = p[i] > 0 ? z[i] + (conjugate ? G / G_before * direction[i] : 0.0) : 0.0;
    }
    G_before = G;
    double along = 0, curvature = 0;
    measure(along, curvature);
    if (!(along > 0)) {
      for (std::size_t i = 0; i < n; ++i) direction[i] = p[i] > 0 ? z[i] : 0.0;
      measure(along, curvature);
    }
    const double step = curvature != 0 ? along / curvature : 0.0;
    before = p;
    bool reentered = false, released = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (p[i] > 0) {
        p[i] -= step * direction[i];
        if (!(p[i] > 0)) p[i] = 0, released = true;
      } else if (gap[i] < 0) {
        p[i] = -step * z[i];
        reentered = true;
      }
    }
    conjugate = !reentered;
    double total = 0;
    for (std::size_t i = 0; i < n; ++i) total += weight(i) * p[i];
    if (!(total > 0)) return before;
    const double scale = mean_pressure * cells / total;
    double change = 0;
    for (std::size_t i = 0; i < n; ++i) p[i] *= scale, change += weight(i) * std::fabs(p[i] - before[i]);
    displaced = !reentered && !released;
    if (displaced) {
      for (std::size_t i = 0; i < n; ++i) u[i] = scale * (u[i] - step * response[i]);
    }
    if (change < settled * mean_pressure * cells && iteration > 2) break;
  }
  return p;
}

// The end of a run of contact cells beyond its last cell j (towards `direction`): the
// pressure goes like the root of the distance to the end, p^2 linearly, through the last two
// cells (half a cell out for a run of one cell); short of the next cell.
double run_end(const std::vector<double>& p, std::size_t j, int direction, bool single, double cell) {
  const double x = cell * static_cast<double>(j);
  const double next_in = single ? 0.0 : p[direction > 0 ? j - 1 : j + 1];
  const double last = p[j] * p[j], inner = next_in * next_in;
  const double beyond = inner > last ? cell * last / (inner - last) : cell / 2;
  return x + direction * std::min(beyond, 0.9 * cell);
}

// The fewest cells a period. A seed of a roughness of n <= 32 needs no more than 1024 (32 a
// shortest wavelength): at 4096, the bench's map of 10^4 points (n = 8 to 32) spent 1.3 of its
// 6.6 s of CPU time in the seeds' iterations (60 on average, each two transforms), and took
// 14 % less wall time at 1024 with the same contacts (fractions within 5e-11, the same zones);
// single solves of its points 25 % less.
constexpr int fewest_cells = 1024;

}  // namespace

int seed_cells(const SurfaceModel& surface) {
  const double wanted = 32 * (2 * pi) / (2 * surface.resolution);
  int cells = fewest_cells;
  while (cells < wanted && cells < (1 << 17)) cells *= 2;
  return cells;
}

Configuration grid_seed(const SurfaceModel& surface, double P, int cells, int nodes) {
  const double cell = 2 * pi / cells;
  const std::size_t half = static_cast<std::size_t>(cells / 2);
  std::vector<double> xs(half + 1), clearance(half + 1);  // the half period: the surface is even
  for (std::size_t i = 0; i <= half; ++i) xs[i] = cell * static_cast<double>(i);
  surface.height_differences(xs.data(), xs.size(), surface.top_angle, clearance.data());
  for (double& depth : clearance) depth = -depth;
  const std::vector<double> p = grid_pressure(clearance, surface.E, P / (2 * pi));

  Configuration c;
  for (std::size_t i = 0; i <= half; ++i) {
    if (!(p[i] > 0)) continue;
    std::size_t j = i;
    while (j + 1 <= half && p[j + 1] > 0) ++j;
    const double a = i == 0 ? 0.0 : std::max(run_end(p, i, -1, i == j, cell), 0.25 * cell);
    const double b = j == half ? pi : std::min(run_end(p, j, +1, i == j, cell), pi - 0.25 * cell);
    i = j;
    ZoneUnknowns z{ZoneGeometry(a, b), std::vector<double>(static_cast<std::size_t>(nodes), 0.0)};
    // sum_j d_j T_j(tau) = q sqrt(1 - tau^2), q = p / sin x^, p by linear interpolation.
    const std::vector<double> x = z.geometry.angles_of(chebyshev::nodes(nodes));
    std::vector<double> values(static_cast<std::size_t>(nodes));
    for (int k = 0; k < nodes; ++k) {
      const double at = x[static_cast<std::size_t>(k)] / cell;
      const std::size_t below = std::min(static_cast<std::size_t>(at), half - 1);
      const double t = at - static_cast<double>(below);
      const double pressure = std::max(0.0, (1 - t) * p[below] + t * p[below + 1]);
      const double root = std::sin(pi * (k + 0.5) / nodes);
      values[static_cast<std::size_t>(k)] = pressure * root / std::sin(x[static_cast<std::size_t>(k)]);
    }
    chebyshev::coefficients(values.data(), nodes, z.d.data());
    c.zones.push_back(std::move(z));
  }
  return c;
}

}  // namespace wavecontact::detail
