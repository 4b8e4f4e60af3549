#include "grid_seed.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include <unsupported/Eigen/FFT>

#include "chebyshev.hpp"
#include "constants.hpp"

namespace wavecontact::detail {

namespace {

constexpr int most_iterations = 4000;
constexpr double settled = 1e-9;  // the pressure's relative change per iteration at the end

// The displacement of the periodic half-plane under a pressure constant on each cell:
// u_k = 2 p_k / (E* |k|) (the pressure's mean moves nothing: u's mean is 0).
class Compliance {
 public:
  Compliance(int cells, double E) : factor_(static_cast<std::size_t>(cells / 2 + 1)) {
    factor_[0] = 0;
    for (int k = 1; k <= cells / 2; ++k) factor_[static_cast<std::size_t>(k)] = 2.0 / (E * k);
    fft_.SetFlag(Eigen::FFT<double>::HalfSpectrum);
  }
  void apply(const std::vector<double>& p, std::vector<double>& u) {
    fft_.fwd(spectrum_, p);
    for (std::size_t k = 0; k < factor_.size(); ++k) spectrum_[k] *= factor_[k];
    fft_.inv(u, spectrum_);
  }

 private:
  std::vector<double> factor_;
  Eigen::FFT<double> fft_;
  std::vector<std::complex<double>> spectrum_;
};

// Polonsky and Keer's iteration: conjugate gradients on the cells in contact, the gap's mean
// there as the rigid approach, cells that penetrate brought back in, the load kept.
std::vector<double> grid_pressure(const std::vector<double>& clearance, double E, double mean_pressure) {
  const std::size_t n = clearance.size();
  Compliance compliance(static_cast<int>(n), E);
  std::vector<double> p(n, mean_pressure), u(n), gap(n), direction(n, 0.0), response(n), before(n);
  double G_before = 1;
  bool conjugate = false;
  for (int iteration = 0; iteration < most_iterations; ++iteration) {
    compliance.apply(p, u);
    double approach = 0;
    std::size_t contact = 0;
    for (std::size_t i = 0; i < n; ++i) {
      gap[i] = clearance[i] + u[i];
      if (p[i] > 0) approach += gap[i], ++contact;
    }
    approach /= static_cast<double>(contact);
    double G = 0;
    for (std::size_t i = 0; i < n; ++i) {
      gap[i] -= approach;
      if (p[i] > 0) G += gap[i] * gap[i];
    }
    for (std::size_t i = 0; i < n; ++i) {
      direction[i] = p[i] > 0 ? gap[i] + (conjugate ? G / G_before * direction[i] : 0.0) : 0.0;
    }
    G_before = G;
    compliance.apply(direction, response);
    double response_mean = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (p[i] > 0) response_mean += response[i];
    }
    response_mean /= static_cast<double>(contact);
    double along = 0, curvature = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (p[i] > 0) along += gap[i] * direction[i], curvature += (response[i] - response_mean) * direction[i];
    }
    const double step = curvature != 0 ? along / curvature : 0.0;
    before = p;
    bool reentered = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (p[i] > 0) {
        p[i] = std::max(0.0, p[i] - step * direction[i]);
      } else if (gap[i] < 0) {
        p[i] = -step * gap[i];
        reentered = true;
      }
    }
    conjugate = !reentered;
    double total = 0;
    for (double v : p) total += v;
    if (!(total > 0)) return before;
    const double scale = mean_pressure * static_cast<double>(n) / total;
    double change = 0;
    for (std::size_t i = 0; i < n; ++i) p[i] *= scale, change += std::fabs(p[i] - before[i]);
    if (change < settled * mean_pressure * static_cast<double>(n) && iteration > 2) break;
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

}  // namespace

int seed_cells(const SurfaceModel& surface) {
  const double wanted = 32 * (2 * pi) / (2 * surface.resolution);
  int cells = 4096;
  while (cells < wanted && cells < (1 << 17)) cells *= 2;
  return cells;
}

Configuration grid_seed(const SurfaceModel& surface, double P, int cells, int nodes) {
  const double cell = 2 * pi / cells;
  const std::size_t half = static_cast<std::size_t>(cells / 2);
  std::vector<double> clearance(static_cast<std::size_t>(cells));
  for (std::size_t i = 0; i <= half; ++i) clearance[i] = -surface.depth(cell * static_cast<double>(i));
  for (std::size_t i = half + 1; i < clearance.size(); ++i) clearance[i] = clearance[clearance.size() - i];
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
