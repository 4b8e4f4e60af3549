#include "zone_preconditioner.hpp"

#include <cmath>

#include "chebyshev.hpp"
#include "constants.hpp"
#include "support/parallel.hpp"
#include "zone_field.hpp"

namespace wavecontact::detail {

Eigen::VectorXd ZonePreconditioner::Block::solve(const double* r) const {
  // r: the block's rows (collocation, end conditions); the result in its unknowns' order
  // (ends, coefficients).
  Eigen::VectorXd y(ends + count);
  Eigen::VectorXd Dr(count);
  for (int j = 0; j < count; ++j) Dr[j] = r[j] / diagonal[static_cast<std::size_t>(j)];
  EndVector e = EndVector::Zero(ends);
  if (ends > 0) {
    EndVector rhs = S * Dr;
    for (int i = 0; i < ends; ++i) rhs[i] -= r[count + i];
    e = schur.solve(rhs);
  }
  const Eigen::VectorXd Ee = E * e;
  for (int i = 0; i < ends; ++i) y[i] = e[i];
  for (int j = 0; j < count; ++j) y[ends + j] = (r[j] - Ee[j]) / diagonal[static_cast<std::size_t>(j)];
  return y;
}

ZonePreconditioner::ZonePreconditioner(const SurfaceModel& surface, const Configuration& c, const SystemLayout& L,
                                       const std::vector<std::vector<double>>& external_slope, double P)
    : C_scale_(L.C_scale), C_at_(L.C_at) {
  const std::size_t K = c.zones.size();
  const Eigen::Index n = static_cast<Eigen::Index>(K);
  coupling_ = Eigen::MatrixXd::Zero(n, n);
  for_each_index(K, zones_for_threads, [&](std::size_t k) {  // each row on its own
    const ZoneGeometry& gk = c.zones[k].geometry;
    const HalfAngle centre = HalfAngle::of((gk.a + gk.b) / 2);
    for (std::size_t l = 0; l < K; ++l) {
      if (l == k) continue;
      const ZoneGeometry& gl = c.zones[l].geometry;
      const double unit[1] = {1 / (pi * gl.h)};  // d_0 of a unit load
      coupling_(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(l)) = far_potential(gl, unit, 1, centre);
    }
  });
  for (std::size_t k = 0; k < K; ++k) {
    const ZoneUnknowns& z = c.zones[k];
    const SystemLayout::Zone& lz = L.zones[k];
    const ZoneGeometry& g = z.geometry;
    const int M = lz.count, f = lz.free_ends;
    Block b;
    b.at = lz.at, b.ends = f, b.count = M;
    const double lambda = self_logarithm(g);
    b.diagonal.resize(static_cast<std::size_t>(M));
    b.diagonal[0] = lambda;
    for (int j = 1; j < M; ++j) b.diagonal[static_cast<std::size_t>(j)] = 1;  // row j is j (own_j - G_j)
    b.S = Eigen::MatrixXd(f, M);
    for (int e = 0; e < f; ++e) {
      const bool plus = lz.a_free && e == 0;  // the first end row is tau = +1 when a is free
      for (int j = 0; j < M; ++j) b.S(e, j) = plus ? 1.0 : (j % 2 == 0 ? 1.0 : -1.0);
    }
    // End columns: the own potential's change with h, minus the transform of the field's
    // slope at the nodes times their motion.
    b.E = Eigen::MatrixXd(M, f);
    b.load_row = Eigen::VectorXd::Zero(f + M);
    b.load_row[f] = pi * lz.row_scale;  // W = pi h d_0
    if (f > 0) {
      const std::vector<double>& tau = chebyshev::nodes(M);
      const std::vector<double> x = g.angles_of(tau);
      std::vector<double> field_slope(static_cast<std::size_t>(M));
      for (int i = 0; i < M; ++i) {
        const std::size_t u = static_cast<std::size_t>(i);
        field_slope[u] = surface.E / 2 * (-surface.slope(x[u]) / std::sin(x[u])) - external_slope[k][u];
      }
      int column = 0;
      for (int which = 0; which < 2; ++which) {
        if ((which == 0 && !lz.a_free) || (which == 1 && !lz.b_free)) continue;
        const double dh = which == 0 ? g.dh_da() : g.dh_db(), dm = which == 0 ? g.dm_da() : g.dm_db();
        // d(angle)/d(unknown) where the end is now: the unknown is 1 -+ s in units of the
        // zone's half-width at the start, d(1 -+ s)/dx = +-sin x.
        const bool upper = which == 0 ? lz.a_upper : lz.b_upper;
        const double rate = (upper ? 1 : -1) * lz.end_scale / std::sin(which == 0 ? g.a : g.b);
        std::vector<double> motion(static_cast<std::size_t>(M)), T(static_cast<std::size_t>(M));
        for (int i = 0; i < M; ++i) {
          const std::size_t u = static_cast<std::size_t>(i);
          motion[u] = field_slope[u] * (dm + tau[u] * dh);
        }
        chebyshev::coefficients(motion.data(), M, T.data());
        for (int j = 0; j < M; ++j) {
          const std::size_t u = static_cast<std::size_t>(j);
          // The own potential at fixed h d: log(2/h) h d_0 and h d_j / j.
          const double own = j == 0 ? -z.d[0] * dh : 0.0;
          b.E(j, column) = (j == 0 ? 1 : j) * (own - T[u]) * rate / lz.row_scale;
        }
        ++column;
      }
      Eigen::MatrixXd DE = b.E;
      for (int j = 0; j < M; ++j) DE.row(j) /= b.diagonal[static_cast<std::size_t>(j)];
      b.schur.compute(EndMatrix(b.S * DE));
    }
    std::vector<double> e0(static_cast<std::size_t>(f + M), 0.0);
    e0[0] = 1 / lz.row_scale;  // the block's first row: T_0
    b.g = b.solve(e0.data());
    b.delta = b.load_row.dot(b.g);
    blocks_.push_back(std::move(b));
  }
  // The coarse system: (I + Delta G) w - Delta 1 c = t, (2/P) 1^T w = r_load.
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n + 1, n + 1);
  for (Eigen::Index k = 0; k < n; ++k) {
    const Block& b = blocks_[static_cast<std::size_t>(k)];
    A(k, k) += 1;
    A.row(k).head(n) += b.delta * coupling_.row(k);
    A(k, n) = -b.delta * C_scale_;
    A(n, k) = 2 / P;
  }
  coarse_.compute(A);
}

std::vector<double> ZonePreconditioner::apply(const std::vector<double>& r) const {
  const Eigen::Index K = static_cast<Eigen::Index>(blocks_.size());
  std::vector<double> y(r.size(), 0.0);
  std::vector<Eigen::VectorXd> local(blocks_.size());
  Eigen::VectorXd rhs(K + 1);
  for (Eigen::Index k = 0; k < K; ++k) {
    const Block& b = blocks_[static_cast<std::size_t>(k)];
    local[static_cast<std::size_t>(k)] = b.solve(r.data() + b.at);
    rhs[k] = b.load_row.dot(local[static_cast<std::size_t>(k)]);
  }
  rhs[K] = r[C_at_];
  const Eigen::VectorXd wc = coarse_.solve(rhs);
  const Eigen::VectorXd field = coupling_ * wc.head(K);
  for (Eigen::Index k = 0; k < K; ++k) {
    const Block& b = blocks_[static_cast<std::size_t>(k)];
    const Eigen::VectorXd yk = local[static_cast<std::size_t>(k)] - b.g * (field[k] - C_scale_ * wc[K]);
    for (int i = 0; i < b.ends + b.count; ++i) y[b.at + static_cast<std::size_t>(i)] = yk[i];
  }
  y[C_at_] = wc[K];
  return y;
}

}  // namespace wavecontact::detail
