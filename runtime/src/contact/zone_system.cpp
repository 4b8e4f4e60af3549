#include "zone_system.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <Eigen/Dense>

#include "chebyshev.hpp"
#include "constants.hpp"
#include "gmres.hpp"
#include "zone_field.hpp"

namespace wavecontact::detail {

namespace {

constexpr double tiny = std::numeric_limits<double>::min();

// The angles of the zone's Chebyshev nodes.
std::vector<double> node_angles(const ZoneGeometry& g, int count) { return g.angles_of(chebyshev::nodes(count)); }

}  // namespace

// Where each zone's unknowns and rows are in the packed vectors, and their scales: a zone's
// ends in units of its half-width in x^, its coefficients in units of their magnitude, its
// rows in units of its own potential's magnitude.
struct ZoneSystem::Layout {
  struct Zone {
    std::size_t at = 0;  // first unknown (= first row) of the zone's block
    int free_ends = 0, count = 0;
    double end_scale = 1, d_scale = 1, row_scale = 1;
    bool top = false, valley = false;
    double birth_load = -1;  // carried through (ZoneUnknowns)
    int block() const { return free_ends + count; }
  };
  std::vector<Zone> zones;
  std::size_t C_at = 0, size = 0;
  double C_scale = 1;
};

ZoneSystem::Layout ZoneSystem::layout(const Configuration& c) const {
  Layout L;
  std::size_t at = 0;
  double largest_row = 0;
  for (const ZoneUnknowns& z : c.zones) {
    Layout::Zone lz;
    lz.at = at;
    lz.free_ends = z.geometry.free_ends();
    lz.count = static_cast<int>(z.d.size());
    lz.top = z.geometry.top(), lz.valley = z.geometry.valley();
    lz.birth_load = z.birth_load;
    lz.end_scale = (z.geometry.b - z.geometry.a) / 2;
    double magnitude = 0;
    for (double v : z.d) magnitude += std::fabs(v);
    lz.d_scale = std::max(magnitude, tiny);
    lz.row_scale = z.geometry.h * lz.d_scale;
    largest_row = std::max(largest_row, lz.row_scale);
    at += static_cast<std::size_t>(lz.block());
    L.zones.push_back(lz);
  }
  L.C_at = at;
  L.size = at + 1;
  L.C_scale = std::max(std::fabs(c.C), largest_row);
  return L;
}

std::vector<double> ZoneSystem::pack(const Configuration& c, const Layout& L) const {
  std::vector<double> X(L.size);
  for (std::size_t k = 0; k < c.zones.size(); ++k) {
    const Layout::Zone& lz = L.zones[k];
    const ZoneGeometry& g = c.zones[k].geometry;
    std::size_t i = lz.at;
    if (!lz.top) X[i++] = g.a / lz.end_scale;
    if (!lz.valley) X[i++] = g.b / lz.end_scale;
    for (double v : c.zones[k].d) X[i++] = v / lz.d_scale;
  }
  X[L.C_at] = c.C / L.C_scale;
  return X;
}

Configuration ZoneSystem::unpack(const std::vector<double>& X, const Layout& L) const {
  Configuration c;
  for (const Layout::Zone& lz : L.zones) {
    std::size_t i = lz.at;
    const double a = lz.top ? 0.0 : X[i++] * lz.end_scale;
    const double b = lz.valley ? pi : X[i++] * lz.end_scale;
    ZoneUnknowns z{ZoneGeometry(a, b), std::vector<double>(static_cast<std::size_t>(lz.count)), lz.birth_load};
    for (double& v : z.d) v = X[i++] * lz.d_scale;
    c.zones.push_back(std::move(z));
  }
  c.C = X[L.C_at] * L.C_scale;
  return c;
}

ZoneFields zone_fields(const SurfaceModel& surface, const Configuration& c) {
  ZoneFields f;
  for (const ZoneUnknowns& z : c.zones) f.kinks.push_back(KinkCorrection::of(surface, z.geometry));
  return f;
}

double zone_potential(const Configuration& c, const ZoneFields& fields, std::size_t k, double x) {
  const ZoneUnknowns& z = c.zones[k];
  const double smooth = far_potential(z.geometry, z.d.data(), static_cast<int>(z.d.size()), x);
  return fields.kinks[k] ? smooth + fields.kinks[k]->potential(x) : smooth;
}

double zone_load(const Configuration& c, const ZoneFields& fields, std::size_t k) {
  const double smooth = pi * c.zones[k].geometry.h * c.zones[k].d[0];
  return fields.kinks[k] ? smooth + fields.kinks[k]->load() : smooth;
}

double ZoneSystem::field_of_others(const Configuration& c, const ZoneFields& fields, std::size_t skip, double x) const {
  double sum = 0;
  for (std::size_t l = 0; l < c.zones.size(); ++l) {
    if (l != skip) sum += zone_potential(c, fields, l, x);
  }
  return sum;
}

std::vector<double> ZoneSystem::residual(const Configuration& c, const Layout& L,
                                         std::vector<std::vector<double>>* external_slope) const {
  std::vector<double> F(L.size, 0.0);
  const double half_E = surface_.E / 2;
  const ZoneFields fields = zone_fields(surface_, c);
  if (external_slope) external_slope->assign(c.zones.size(), {});
  double load = 0;
  for (std::size_t k = 0; k < c.zones.size(); ++k) {
    const ZoneUnknowns& zk = c.zones[k];
    const Layout::Zone& lz = L.zones[k];
    const int M = lz.count;
    const std::vector<double> x = node_angles(zk.geometry, M);
    // (E/2) (y - y(x_ref)) - sum of the others' potentials at the nodes; the constant part
    // (E/2) y(x_ref) + C joins the T_0 coefficient.
    const double x_ref = x[static_cast<std::size_t>(M / 2)];
    std::vector<double> values(static_cast<std::size_t>(M)), slope_ext;
    if (external_slope) slope_ext.assign(static_cast<std::size_t>(M), 0.0);
    for (int i = 0; i < M; ++i) {
      const double xi = x[static_cast<std::size_t>(i)];
      double v = half_E * surface_.height_difference(xi, x_ref);
      if (fields.kinks[k]) v -= fields.kinks[k]->potential(xi);
      for (std::size_t l = 0; l < c.zones.size(); ++l) {
        if (l == k) continue;
        const ZoneUnknowns& zl = c.zones[l];
        if (external_slope) {  // the kink correction's slope is left out: for the preconditioner
          const FieldValue f = far_field(zl.geometry, zl.d.data(), static_cast<int>(zl.d.size()), xi);
          v -= f.potential + (fields.kinks[l] ? fields.kinks[l]->potential(xi) : 0.0);
          slope_ext[static_cast<std::size_t>(i)] += f.slope;
        } else {
          v -= zone_potential(c, fields, l, xi);
        }
      }
      values[static_cast<std::size_t>(i)] = v;
    }
    if (external_slope) (*external_slope)[k] = std::move(slope_ext);
    std::vector<double> G(static_cast<std::size_t>(M)), own(static_cast<std::size_t>(M));
    chebyshev::coefficients(values.data(), M, G.data());
    G[0] += half_E * surface_.depth(x_ref) + c.C;
    own_potential(zk.geometry, zk.d.data(), M, own.data());
    std::size_t row = lz.at;
    for (int j = 0; j < M; ++j) F[row++] = (own[static_cast<std::size_t>(j)] - G[static_cast<std::size_t>(j)]) / lz.row_scale;
    for (double e : end_conditions(zk.geometry, zk.d.data(), M)) F[row++] = e / lz.d_scale;
    load += 2 * zone_load(c, fields, k);
  }
  F[L.C_at] = (load - closure_.P) / closure_.P;
  return F;
}

std::vector<double> ZoneSystem::residuals(const Configuration& c) const { return residual(c, layout(c), nullptr); }

void ZoneSystem::relax(Configuration& c) const {
  const double half_E = surface_.E / 2;
  const ZoneFields fields = zone_fields(surface_, c);
  std::vector<std::vector<double>> next;
  for (std::size_t k = 0; k < c.zones.size(); ++k) {
    const ZoneUnknowns& zk = c.zones[k];
    const int M = static_cast<int>(zk.d.size());
    const std::vector<double> x = node_angles(zk.geometry, M);
    const double x_ref = x[static_cast<std::size_t>(M / 2)];
    std::vector<double> values(static_cast<std::size_t>(M)), G(static_cast<std::size_t>(M));
    for (int i = 0; i < M; ++i) {
      const double xi = x[static_cast<std::size_t>(i)];
      values[static_cast<std::size_t>(i)] = half_E * surface_.height_difference(xi, x_ref) - field_of_others(c, fields, k, xi) -
                                            (fields.kinks[k] ? fields.kinks[k]->potential(xi) : 0.0);
    }
    chebyshev::coefficients(values.data(), M, G.data());
    G[0] += half_E * surface_.depth(x_ref) + c.C;
    std::vector<double> d(static_cast<std::size_t>(M));
    d[0] = G[0] / (zk.geometry.h * self_logarithm(zk.geometry));
    for (int j = 1; j < M; ++j) d[static_cast<std::size_t>(j)] = j * G[static_cast<std::size_t>(j)] / zk.geometry.h;
    next.push_back(std::move(d));
  }
  for (std::size_t k = 0; k < c.zones.size(); ++k) c.zones[k].d = std::move(next[k]);
}

namespace {

// The preconditioner of one Newton step: each zone's block of the Jacobian with the others
// frozen (LU), and the coupling of the zones' T_0 rows through their loads W_l = pi h_l d_l0
// and C, solved exactly (Woodbury: a dense system of one unknown a zone, and C).
class Preconditioner {
 public:
  struct Block {
    std::size_t at;
    int size;
    Eigen::PartialPivLU<Eigen::MatrixXd> lu;
    Eigen::VectorXd load_row;  // V_k: dW_k / d(unknowns), scaled
    double row_scale;
    Eigen::VectorXd g;  // B^-1 e_0 / row_scale
    double delta;       // V g
  };

  std::vector<Block> blocks;
  Eigen::MatrixXd coupling;  // G_kl, the T_0 potential on zone k of a unit load on zone l
  double C_scale = 1, P = 1;
  Eigen::PartialPivLU<Eigen::MatrixXd> coarse;
  std::size_t C_at = 0;

  void factor() {
    const Eigen::Index K = static_cast<Eigen::Index>(blocks.size());
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(K + 1, K + 1);
    for (Eigen::Index k = 0; k < K; ++k) {
      Block& b = blocks[static_cast<std::size_t>(k)];
      Eigen::VectorXd e0 = Eigen::VectorXd::Zero(b.size);
      e0[0] = 1 / b.row_scale;  // the T_0 row is the block's first after its ends? see below
      b.g = b.lu.solve(e0);
      b.delta = b.load_row.dot(b.g);
      A(k, k) += 1;
      for (Eigen::Index l = 0; l < K; ++l) A(k, l) += b.delta * coupling(k, l);
      A(k, K) = -b.delta * C_scale;
      A(K, k) = 2 / P;
    }
    coarse.compute(A);
  }

  std::vector<double> apply(const std::vector<double>& r) const {
    const Eigen::Index K = static_cast<Eigen::Index>(blocks.size());
    std::vector<double> y(r.size(), 0.0);
    std::vector<Eigen::VectorXd> local(blocks.size());
    Eigen::VectorXd rhs(K + 1);
    for (Eigen::Index k = 0; k < K; ++k) {
      const Block& b = blocks[static_cast<std::size_t>(k)];
      const Eigen::Map<const Eigen::VectorXd> rk(r.data() + b.at, b.size);
      local[static_cast<std::size_t>(k)] = b.lu.solve(rk);
      rhs[k] = b.load_row.dot(local[static_cast<std::size_t>(k)]);
    }
    rhs[K] = r[C_at];
    const Eigen::VectorXd wc = coarse.solve(rhs);
    const Eigen::VectorXd field = coupling * wc.head(K);
    for (Eigen::Index k = 0; k < K; ++k) {
      const Block& b = blocks[static_cast<std::size_t>(k)];
      const Eigen::VectorXd yk = local[static_cast<std::size_t>(k)] - b.g * (field[k] - C_scale * wc[K]);
      for (int i = 0; i < b.size; ++i) y[b.at + static_cast<std::size_t>(i)] = yk[i];
    }
    y[C_at] = wc[K];
    return y;
  }
};

}  // namespace

ZoneSystem::Result ZoneSystem::newton(Configuration c, double tolerance,
                                      const std::function<void()>& checkpoint) const {
  Result result;
  const Layout L = layout(c);
  std::vector<double> X = pack(c, L);
  std::vector<std::vector<double>> slope_ext;
  std::vector<double> F = residual(c, L, &slope_ext);
  const auto norm = [](const std::vector<double>& v) {  // infinite if any is not a number
    double m = 0;
    for (double e : v) {
      if (!(std::fabs(e) <= m)) m = std::isnan(e) ? std::numeric_limits<double>::infinity() : std::fabs(e);
    }
    return m;
  };
  std::size_t closing = std::numeric_limits<std::size_t>::max();
  double best = std::numeric_limits<double>::infinity();
  int stalled = 0;  // iterations without halving the best residual
  for (int iteration = 0; iteration < 40; ++iteration) {
    if (checkpoint) checkpoint();
    result.iterations = iteration;
    result.residual = norm(F);
    if (!(result.residual < std::numeric_limits<double>::infinity())) {
      result.outcome = Outcome::failed;
      result.configuration = c;
      return result;
    }
    if (result.residual < tolerance) {
      result.outcome = Outcome::converged;
      result.configuration = c;
      return result;
    }
    if (result.residual < 0.5 * best) {
      best = result.residual, stalled = 0;
    } else if (++stalled >= 8) {
      // No progress: rounding reached (a profile's heights carry their own), or failed.
      result.outcome = best < 1e-8 ? Outcome::converged : Outcome::failed;
      result.configuration = c;
      return result;
    }
    // The preconditioner at c.
    Preconditioner pre;
    pre.C_scale = L.C_scale, pre.P = closure_.P, pre.C_at = L.C_at;
    const std::size_t K = c.zones.size();
    pre.coupling = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(K), static_cast<Eigen::Index>(K));
    for (std::size_t k = 0; k < K; ++k) {
      const ZoneGeometry& gk = c.zones[k].geometry;
      const double centre = (gk.a + gk.b) / 2;
      for (std::size_t l = 0; l < K; ++l) {
        if (l == k) continue;
        const ZoneGeometry& gl = c.zones[l].geometry;
        const double unit[1] = {1 / (pi * gl.h)};  // d_0 of a unit load
        pre.coupling(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(l)) = far_potential(gl, unit, 1, centre);
      }
    }
    for (std::size_t k = 0; k < K; ++k) {
      const ZoneUnknowns& z = c.zones[k];
      const Layout::Zone& lz = L.zones[k];
      const ZoneGeometry& g = z.geometry;
      const int M = lz.count, f = lz.free_ends, n = lz.block();
      Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, n);
      // Rows: M collocation rows, then f end rows. Columns: f ends, then M coefficients.
      const double lambda = self_logarithm(g);
      B(0, f) = lambda;
      for (int j = 1; j < M; ++j) B(j, f + j) = 1.0 / j;
      for (int e = 0; e < f; ++e) {
        const bool plus = !lz.top && e == 0;  // the first end row is tau = +1 unless the top
        for (int j = 0; j < M; ++j) B(M + e, f + j) = plus ? 1.0 : (j % 2 == 0 ? 1.0 : -1.0);
      }
      // End columns: the own potential's change with h, minus the transform of the field's
      // slope at the nodes times their motion.
      const std::vector<double>& tau = chebyshev::nodes(M);
      const std::vector<double> x = node_angles(g, M);
      std::vector<double> field_slope(static_cast<std::size_t>(M));
      for (int i = 0; i < M; ++i) {
        const double xi = x[static_cast<std::size_t>(i)];
        const double dY_ds = -surface_.slope(xi) / std::sin(xi);
        field_slope[static_cast<std::size_t>(i)] = surface_.E / 2 * dY_ds - slope_ext[k][static_cast<std::size_t>(i)];
      }
      int column = 0;
      for (int which = 0; which < 2; ++which) {
        if ((which == 0 && lz.top) || (which == 1 && lz.valley)) continue;
        const double dh = which == 0 ? g.dh_da() : g.dh_db(), dm = which == 0 ? g.dm_da() : g.dm_db();
        std::vector<double> motion(static_cast<std::size_t>(M)), T(static_cast<std::size_t>(M));
        for (int i = 0; i < M; ++i) {
          motion[static_cast<std::size_t>(i)] = field_slope[static_cast<std::size_t>(i)] * (dm + tau[static_cast<std::size_t>(i)] * dh);
        }
        chebyshev::coefficients(motion.data(), M, T.data());
        for (int j = 0; j < M; ++j) {
          const double own = j == 0 ? z.d[0] * (lambda - 1) * dh : z.d[static_cast<std::size_t>(j)] / j * dh;
          B(j, column) = (own - T[static_cast<std::size_t>(j)]) * lz.end_scale / lz.row_scale;
        }
        ++column;
      }
      // B's rows are in F's order (collocation, ends) and its columns in X's (ends, d).
      Preconditioner::Block block;
      block.at = lz.at, block.size = n, block.row_scale = lz.row_scale;
      block.lu.compute(B);
      block.load_row = Eigen::VectorXd::Zero(n);
      block.load_row[f] = pi * g.h * lz.d_scale;
      column = 0;
      for (int which = 0; which < 2; ++which) {
        if ((which == 0 && lz.top) || (which == 1 && lz.valley)) continue;
        block.load_row[column++] = pi * z.d[0] * (which == 0 ? g.dh_da() : g.dh_db()) * lz.end_scale;
      }
      pre.blocks.push_back(std::move(block));
    }
    pre.factor();
    // GMRES on J M^-1 z = -F, J v by a difference of residuals.
    const auto jacobian_times = [&](const std::vector<double>& v) {
      double vn = 0;
      for (double e : v) vn = std::max(vn, std::fabs(e));
      if (vn == 0) return std::vector<double>(v.size(), 0.0);
      const double h = 1e-7 / vn;
      std::vector<double> Xh = X;
      for (std::size_t i = 0; i < X.size(); ++i) Xh[i] += h * v[i];
      std::vector<double> Fh = residual(unpack(Xh, L), L, nullptr);
      for (std::size_t i = 0; i < Fh.size(); ++i) Fh[i] = (Fh[i] - F[i]) / h;
      return Fh;
    };
    std::vector<double> minus_F(F.size());
    for (std::size_t i = 0; i < F.size(); ++i) minus_F[i] = -F[i];
    const double forcing = std::min(1e-2, std::max(1e-8, result.residual));
    const std::vector<double> step =
        gmres(jacobian_times, [&](const std::vector<double>& v) { return pre.apply(v); }, minus_F, forcing, 60, 3);
    // Damping: every stretch between consecutive ends keeps a tenth of its length; a step
    // that would close one twice running is an event.
    const Configuration full = unpack([&] {
      std::vector<double> Xs = X;
      for (std::size_t i = 0; i < X.size(); ++i) Xs[i] += step[i];
      return Xs;
    }(), L);
    std::vector<double> ends{0}, moved{0};
    for (std::size_t k = 0; k < K; ++k) {
      ends.push_back(c.zones[k].geometry.a), ends.push_back(c.zones[k].geometry.b);
      moved.push_back(full.zones[k].geometry.a), moved.push_back(full.zones[k].geometry.b);
    }
    ends.push_back(pi), moved.push_back(pi);
    double lambda = 1;
    std::size_t limiting = 0;
    for (std::size_t e = 0; e + 1 < ends.size(); ++e) {
      const double length = ends[e + 1] - ends[e];
      const double shrink = length - (moved[e + 1] - moved[e]);
      if (length > 0 && shrink > 0 && lambda * shrink > 0.9 * length) lambda = 0.9 * length / shrink, limiting = e;
    }
    // A full step that would close the stretch twice running, or a stretch already next to
    // nothing, is an event: a gap between zones closing, a zone reaching the top or the valley
    // (within a resolution), or a zone vanishing (a thousandth of one).
    const double length = ends[limiting + 1] - ends[limiting];
    const double shrink = length - (moved[limiting + 1] - moved[limiting]);
    const bool overshoots = lambda < 1 && shrink >= length;
    const bool zone = limiting % 2 == 1;
    const double near = (zone ? 1e-3 : 1.0) * surface_.resolution;
    if ((overshoots && closing == limiting && length < near) || (lambda < 1 && length - lambda * shrink < 1e-9 * pi)) {
      result.outcome = Outcome::stretch_closes;
      result.stretch = limiting;
      result.configuration = c;
      return result;
    }
    closing = overshoots ? limiting : std::numeric_limits<std::size_t>::max();
    // Backtracking while the residual's 2-norm grows (the merit function whose decrease a
    // Newton step guarantees; the largest residual need not fall with it).
    const auto squares = [](const std::vector<double>& v) {
      double sum = 0;
      for (double e : v) sum += e * e;
      return std::isnan(sum) ? std::numeric_limits<double>::infinity() : sum;
    };
    const double merit = squares(F);
    std::vector<double> X_next, F_next;
    Configuration c_next;
    for (int halving = 0;; ++halving, lambda /= 2) {
      X_next = X;
      for (std::size_t i = 0; i < X.size(); ++i) X_next[i] += lambda * step[i];
      c_next = unpack(X_next, L);
      F_next = residual(c_next, L, &slope_ext);
      if (squares(F_next) < (1 - 1e-4 * lambda) * merit || halving == 8) break;
    }
    X = std::move(X_next), F = std::move(F_next), c = std::move(c_next);
  }
  result.outcome = Outcome::failed;
  result.configuration = c;
  result.residual = norm(F);
  return result;
}

}  // namespace wavecontact::detail
