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
  Eigen::VectorXd Dr(count);
  for (int j = 0; j < count; ++j) Dr[j] = r[j] / diagonal[static_cast<std::size_t>(j)];
  if (ends == 0) return Dr;  // E has no column (and no data: its product would offset a null pointer)
  Eigen::VectorXd y(ends + count);
  EndVector rhs = S * Dr;
  for (int i = 0; i < ends; ++i) rhs[i] -= r[count + i];
  const EndVector e = schur.solve(rhs);
  const Eigen::VectorXd Ee = E * e;
  for (int i = 0; i < ends; ++i) y[i] = e[i];
  for (int j = 0; j < count; ++j) y[ends + j] = (r[j] - Ee[j]) / diagonal[static_cast<std::size_t>(j)];
  return y;
}

ZonePreconditioner::ZonePreconditioner(const SurfaceModel& surface, const Configuration& c, const SystemLayout& L,
                                       const std::vector<std::vector<double>>& external_slope, double P)
    : C_scale_(L.C_scale), C_at_(L.C_at) {
  const std::size_t K = c.zones.size();
  moments_ = K <= most_zones_with_first_moments ? 2 : 1;
  const Eigen::Index per_zone = moments_, n = static_cast<Eigen::Index>(K) * per_zone;
  coupling_ = Eigen::MatrixXd::Zero(n, n);
  for_each_index(K, zones_for_threads, [&](std::size_t k) {  // each zone's rows on their own
    // The field's T_0 and T_1 coefficients over zone k from its values at the two Chebyshev
    // points tau = +-1/sqrt(2) (sixteen points gave the same |J M^-1 - I|); its T_0
    // coefficient alone, the loads' coupling only, from its value at the middle.
    const ZoneGeometry& gk = c.zones[k].geometry;
    const double tau = std::sqrt(0.5);
    const std::vector<double> x = per_zone > 1 ? gk.angles_of({tau, -tau}) : std::vector<double>{(gk.a + gk.b) / 2};
    for (std::size_t l = 0; l < K; ++l) {
      if (l == k) continue;
      const ZoneGeometry& gl = c.zones[l].geometry;
      for (Eigen::Index a = 0; a < per_zone; ++a) {
        // d of a unit moment: a unit load (d_0 = 1/(pi h)), a unit first moment about the
        // zone's centre ((pi/2) h^2 d_1).
        const double unit[2] = {a == 0 ? 1 / (pi * gl.h) : 0.0, a == 1 ? 2 / (pi * gl.h * gl.h) : 0.0};
        const Eigen::Index row = static_cast<Eigen::Index>(k) * per_zone,
                           column = static_cast<Eigen::Index>(l) * per_zone + a;
        if (per_zone == 1) {
          coupling_(row, column) = far_potential(gl, unit, 1, HalfAngle::of(x[0]));
          continue;
        }
        const double plus = far_potential(gl, unit, 2, HalfAngle::of(x[0]));
        const double minus = far_potential(gl, unit, 2, HalfAngle::of(x[1]));
        coupling_(row, column) = (plus + minus) / 2;
        coupling_(row + 1, column) = (plus - minus) * tau;
      }
    }
  });
  for (std::size_t k = 0; k < K; ++k) {
    const ZoneUnknowns& z = c.zones[k];
    const SystemLayout::Zone& lz = L.zones[k];
    const ZoneGeometry& g = z.geometry;
    const int M = lz.count, f = lz.free_ends;
    Block b;
    b.at = lz.at, b.ends = f, b.count = M, b.row_scale = lz.row_scale;
    b.first_moment_of_d1 = pi / 2 * g.h * lz.row_scale;
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
        // The first moment W (m - m0) + (pi/2) h^2 d_1 moves with the end at fixed h d.
        b.first_moment_of_end[static_cast<std::size_t>(column)] =
            (pi * g.h * z.d[0] * dm + pi / 2 * g.h * z.d[1] * dh) * rate;
        ++column;
      }
      Eigen::MatrixXd DE = b.E;
      for (int j = 0; j < M; ++j) DE.row(j) /= b.diagonal[static_cast<std::size_t>(j)];
      b.schur.compute(EndMatrix(b.S * DE));
    }
    for (int row = 0; row < moments_; ++row) {
      std::vector<double> e(static_cast<std::size_t>(f + M), 0.0);
      e[static_cast<std::size_t>(row)] = 1 / lz.row_scale;  // the block's rows T_0, T_1
      b.g[static_cast<std::size_t>(row)] = b.solve(e.data());
      for (int a = 0; a < moments_; ++a) b.delta(a, row) = b.moment(b.g[static_cast<std::size_t>(row)], a);
    }
    blocks_.push_back(std::move(b));
  }
  // The coarse system in the moments q and C: q_k + Delta_k ((G q)_k - C e_0) = the moments of
  // the blocks' own solves, (2/P) (the sum of the loads) = r_load.
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n + 1, n + 1);
  for (std::size_t k = 0; k < K; ++k) {
    const Block& b = blocks_[k];
    const Eigen::Index at = static_cast<Eigen::Index>(k) * per_zone;
    for (Eigen::Index a = 0; a < per_zone; ++a) {
      A(at + a, at + a) += 1;
      for (Eigen::Index row = 0; row < per_zone; ++row)
        A.row(at + a).head(n) += b.delta(a, row) * coupling_.row(at + row);
      A(at + a, n) = -b.delta(a, 0) * C_scale_;
    }
    A(n, at) = 2 / P;
  }
  coarse_.compute(A);
}

std::vector<double> ZonePreconditioner::apply(const std::vector<double>& r) const {
  const std::size_t K = blocks_.size();
  const Eigen::Index per_zone = moments_, n = static_cast<Eigen::Index>(K) * per_zone;
  std::vector<double> y(r.size(), 0.0);
  std::vector<Eigen::VectorXd> local(K);
  Eigen::VectorXd rhs(n + 1);
  for (std::size_t k = 0; k < K; ++k) {
    const Block& b = blocks_[k];
    local[k] = b.solve(r.data() + b.at);
    for (Eigen::Index a = 0; a < per_zone; ++a)
      rhs[static_cast<Eigen::Index>(k) * per_zone + a] = b.moment(local[k], static_cast<int>(a));
  }
  rhs[n] = r[C_at_];
  const Eigen::VectorXd qc = coarse_.solve(rhs);
  const Eigen::VectorXd field = coupling_ * qc.head(n);
  for (std::size_t k = 0; k < K; ++k) {
    const Block& b = blocks_[k];
    const Eigen::Index at = static_cast<Eigen::Index>(k) * per_zone;
    Eigen::VectorXd yk = local[k] - b.g[0] * (field[at] - C_scale_ * qc[n]);
    if (per_zone > 1) yk -= b.g[1] * field[at + 1];
    for (int i = 0; i < b.ends + b.count; ++i) y[b.at + static_cast<std::size_t>(i)] = yk[i];
  }
  y[C_at_] = qc[n];
  return y;
}

}  // namespace wavecontact::detail
