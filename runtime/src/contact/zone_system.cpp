#include "zone_system.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <cstdio>
#include <cstdlib>

#include "chebyshev.hpp"
#include "constants.hpp"
#include "gmres.hpp"
#include "zone_preconditioner.hpp"
#include "zone_field.hpp"

namespace wavecontact::detail {

namespace {

constexpr double tiny = std::numeric_limits<double>::min();

// The angles of the zone's Chebyshev nodes.
std::vector<double> node_angles(const ZoneGeometry& g, int count) { return g.angles_of(chebyshev::nodes(count)); }

// An end's unknown (SystemLayout): 1 - s = 2 sin^2(x/2) in the upper half, 1 + s = 2 cos^2(x/2)
// in the lower; and back (the unknown kept within [0, 2]).
double end_unknown(double x, bool upper) {
  const double r = upper ? std::sin(x / 2) : std::cos(x / 2);
  return 2 * r * r;
}
double end_angle(double unknown, bool upper) {
  const double half = 2 * std::asin(std::sqrt(std::clamp(unknown, 0.0, 2.0) / 2));
  return upper ? half : pi - half;
}

}  // namespace

SystemLayout ZoneSystem::layout(const Configuration& c, bool ends_fixed) const {
  SystemLayout L;
  std::size_t at = 0;
  double largest_row = 0;
  for (const ZoneUnknowns& z : c.zones) {
    SystemLayout::Zone lz;
    lz.at = at;
    lz.a_free = !ends_fixed && !z.geometry.top(), lz.b_free = !ends_fixed && !z.geometry.valley();
    lz.a = z.geometry.a, lz.b = z.geometry.b;
    lz.free_ends = (lz.a_free ? 1 : 0) + (lz.b_free ? 1 : 0);
    lz.count = static_cast<int>(z.d.size());
    lz.birth_load = z.birth_load;
    lz.end_scale = z.geometry.h;
    lz.a_upper = z.geometry.a <= pi / 2, lz.b_upper = z.geometry.b <= pi / 2;
    // 1 -+ s = 2 sin^2(x/2), 2 cos^2(x/2): d(1 -+ s)/dx = +-sin x.
    lz.a_rate = (lz.a_upper ? 1 : -1) * lz.end_scale / std::sin(z.geometry.a);
    lz.b_rate = (lz.b_upper ? 1 : -1) * lz.end_scale / std::sin(z.geometry.b);
    double magnitude = 0;
    for (double v : z.d) magnitude += std::fabs(v);
    lz.row_scale = z.geometry.h * std::max(magnitude, tiny);
    largest_row = std::max(largest_row, lz.row_scale);
    at += static_cast<std::size_t>(lz.block());
    L.zones.push_back(lz);
  }
  L.C_at = at;
  L.size = at + 1;
  L.C_scale = std::max(std::fabs(c.C), largest_row);
  return L;
}

std::vector<double> ZoneSystem::pack(const Configuration& c, const SystemLayout& L) const {
  std::vector<double> X(L.size);
  for (std::size_t k = 0; k < c.zones.size(); ++k) {
    const SystemLayout::Zone& lz = L.zones[k];
    const ZoneGeometry& g = c.zones[k].geometry;
    std::size_t i = lz.at;
    if (lz.a_free) X[i++] = end_unknown(g.a, lz.a_upper) / lz.end_scale;
    if (lz.b_free) X[i++] = end_unknown(g.b, lz.b_upper) / lz.end_scale;
    for (double v : c.zones[k].d) X[i++] = g.h * v / lz.row_scale;
  }
  X[L.C_at] = c.C / L.C_scale;
  return X;
}

Configuration ZoneSystem::unpack(const std::vector<double>& X, const SystemLayout& L) const {
  Configuration c;
  for (const SystemLayout::Zone& lz : L.zones) {
    std::size_t i = lz.at;
    const double a = lz.a_free ? end_angle(X[i++] * lz.end_scale, lz.a_upper) : lz.a;
    const double b = lz.b_free ? end_angle(X[i++] * lz.end_scale, lz.b_upper) : lz.b;
    ZoneUnknowns z{ZoneGeometry(a, b), std::vector<double>(static_cast<std::size_t>(lz.count)), lz.birth_load};
    for (double& v : z.d) v = X[i++] * lz.row_scale / z.geometry.h;
    c.zones.push_back(std::move(z));
  }
  c.C = X[L.C_at] * L.C_scale;
  return c;
}

ZoneFields::ZoneFields(const SurfaceModel& surface, const Configuration& c) : tree(c) {
  for (const ZoneUnknowns& z : c.zones) {
    kinks.push_back(KinkCorrection::of(surface, z.geometry));
    if (kinks.back()) kinked.push_back(kinks.size() - 1);
  }
}

void ZoneFields::evaluate(std::size_t skip, const std::vector<double>& x, std::vector<double>& potential,
                          std::vector<double>* slope) const {
  potential.assign(x.size(), 0.0);
  if (slope) slope->assign(x.size(), 0.0);
  tree.add(skip, x.data(), x.size(), potential.data(), slope ? slope->data() : nullptr);
  for (std::size_t l : kinked) {
    if (l == skip) continue;
    for (std::size_t i = 0; i < x.size(); ++i) potential[i] += kinks[l]->potential(x[i]);
  }
}

double ZoneFields::potential(double x, std::size_t skip) const {
  std::vector<double> p;
  evaluate(skip, {x}, p, nullptr);
  return p[0];
}

double zone_load(const Configuration& c, const ZoneFields& fields, std::size_t k) {
  const double smooth = pi * c.zones[k].geometry.h * c.zones[k].d[0];
  return fields.kinks[k] ? smooth + fields.kinks[k]->load() : smooth;
}

std::vector<double> ZoneSystem::residual(const Configuration& c, const SystemLayout& L,
                                         std::vector<std::vector<double>>* external_slope) const {
  std::vector<double> F(L.size, 0.0);
  const double half_E = surface_.E / 2;
  const ZoneFields fields(surface_, c);
  if (external_slope) external_slope->assign(c.zones.size(), {});
  double load = 0;
  for (std::size_t k = 0; k < c.zones.size(); ++k) {
    const ZoneUnknowns& zk = c.zones[k];
    const SystemLayout::Zone& lz = L.zones[k];
    const int M = lz.count;
    const std::vector<double> x = node_angles(zk.geometry, M);
    // (E/2) (y - y(x_ref)) - sum of the others' potentials at the nodes; the constant part
    // (E/2) y(x_ref) + C joins the T_0 coefficient.
    const double x_ref = x[static_cast<std::size_t>(M / 2)];
    std::vector<double> values(static_cast<std::size_t>(M)), others, slope_ext;
    fields.evaluate(k, x, others, external_slope ? &slope_ext : nullptr);
    for (int i = 0; i < M; ++i) {
      const std::size_t u = static_cast<std::size_t>(i);
      values[u] = half_E * surface_.height_difference(x[u], x_ref) - others[u] -
                  (fields.kinks[k] ? fields.kinks[k]->potential(x[u]) : 0.0);
    }
    if (external_slope) (*external_slope)[k] = std::move(slope_ext);
    std::vector<double> G(static_cast<std::size_t>(M)), own(static_cast<std::size_t>(M));
    chebyshev::coefficients(values.data(), M, G.data());
    G[0] += half_E * surface_.depth(x_ref) + c.C;
    own_potential(zk.geometry, zk.d.data(), M, own.data());
    std::size_t row = lz.at;
    for (int j = 0; j < M; ++j) F[row++] = (own[static_cast<std::size_t>(j)] - G[static_cast<std::size_t>(j)]) / lz.row_scale;
    // q bounded at each free end: sum_j d_j T_j(+-1) = 0 (tau = +1 at x^ = a).
    double plus = 0, minus = 0;
    for (int j = 0; j < M; ++j) plus += zk.d[static_cast<std::size_t>(j)], minus += (j % 2 == 0 ? 1 : -1) * zk.d[static_cast<std::size_t>(j)];
    if (lz.a_free) F[row++] = zk.geometry.h * plus / lz.row_scale;
    if (lz.b_free) F[row++] = zk.geometry.h * minus / lz.row_scale;
    load += 2 * zone_load(c, fields, k);
  }
  F[L.C_at] = (load - P_) / P_;
  return F;
}

std::vector<double> ZoneSystem::residuals(const Configuration& c) const { return residual(c, layout(c, false), nullptr); }

void ZoneSystem::relax(Configuration& c) const {
  // Each zone's coefficients from its collocation rows with the others' field as it is:
  // d_j = j G_j / h (j >= 1), d_0 = (G_0 + C) / (h log(2/h)), and C such that they carry P.
  const double half_E = surface_.E / 2;
  const ZoneFields fields(surface_, c);
  std::vector<std::vector<double>> next;
  double kink_load = 0, load_of_C = 0, load_without_C = 0;
  for (std::size_t k = 0; k < c.zones.size(); ++k) {
    const ZoneUnknowns& zk = c.zones[k];
    const int M = static_cast<int>(zk.d.size());
    const std::vector<double> x = node_angles(zk.geometry, M);
    const double x_ref = x[static_cast<std::size_t>(M / 2)];
    std::vector<double> values(static_cast<std::size_t>(M)), G(static_cast<std::size_t>(M)), others;
    fields.evaluate(k, x, others, nullptr);
    for (int i = 0; i < M; ++i) {
      const std::size_t u = static_cast<std::size_t>(i);
      values[u] = half_E * surface_.height_difference(x[u], x_ref) - others[u] -
                  (fields.kinks[k] ? fields.kinks[k]->potential(x[u]) : 0.0);
    }
    chebyshev::coefficients(values.data(), M, G.data());
    G[0] += half_E * surface_.depth(x_ref);
    std::vector<double> d(static_cast<std::size_t>(M));
    const double lambda = self_logarithm(zk.geometry);
    d[0] = G[0] / (zk.geometry.h * lambda);
    for (int j = 1; j < M; ++j) d[static_cast<std::size_t>(j)] = j * G[static_cast<std::size_t>(j)] / zk.geometry.h;
    // The zone carries 2 pi (G_0 + C) / log(2/h) (both halves of the period).
    load_without_C += 2 * pi * G[0] / lambda, load_of_C += 2 * pi / lambda;
    if (fields.kinks[k]) kink_load += 2 * fields.kinks[k]->load();
    next.push_back(std::move(d));
  }
  c.C = (P_ - kink_load - load_without_C) / load_of_C;
  for (std::size_t k = 0; k < c.zones.size(); ++k) {
    next[k][0] += c.C / (c.zones[k].geometry.h * self_logarithm(c.zones[k].geometry));
    c.zones[k].d = std::move(next[k]);
  }
}

ZoneSystem::Result ZoneSystem::newton(Configuration c, double tolerance, const std::function<void()>& checkpoint,
                                      bool ends_fixed) const {
  Result result;
  const SystemLayout L = layout(c, ends_fixed);
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
    } else if (++stalled >= (best < 1e-10 ? 3 : 8)) {
      // No progress: rounding reached (a profile's heights carry their own), or failed.
      result.outcome = best < 1e-8 ? Outcome::converged : Outcome::failed;
      result.configuration = c;
      return result;
    }
    const ZonePreconditioner pre(surface_, c, L, slope_ext, P_);
    // GMRES on J M^-1 z = -F, J v by a difference of residuals.
    static int products = 0, steps = 0; ++steps;
    if (std::getenv("WC_COUNT")) {
      std::size_t arg = 0; for (std::size_t i = 0; i < F.size(); ++i) if (std::fabs(F[i]) > std::fabs(F[arg])) arg = i;
      std::size_t zk = 0; for (std::size_t k = 0; k < L.zones.size(); ++k) if (L.zones[k].at <= arg) zk = k;
      std::fprintf(stderr, "newton step %d (zones %zu, size %zu) res %.3g products so far %d; worst row %zu of zone %zu [%.7g, %.7g] d0 %.3g\n", steps, c.zones.size(), X.size(), result.residual, products, arg - L.zones[zk].at, zk, c.zones[zk].geometry.a, c.zones[zk].geometry.b, c.zones[zk].d[0]);
    }
    const auto jacobian_times = [&](const std::vector<double>& v) {
      ++products;
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
    // The linear solve's tolerance falls like the root of the residual: superlinear
    // convergence without over-solving the first, far steps (Eisenstat and Walker).
    const double forcing = std::min(1e-2, std::max(1e-6, 0.1 * std::sqrt(result.residual)));
    const std::vector<double> step =
        gmres(jacobian_times, [&](const std::vector<double>& v) { return pre.apply(v); }, minus_F, forcing, 60, 3);
    if (std::getenv("WC_COUNT")) {
      const SystemLayout::Zone& lv = L.zones.back();
      std::vector<double> Js = jacobian_times(step);
      double r2 = 0, f2 = 0; for (std::size_t i = 0; i < F.size(); ++i) r2 += (Js[i] + F[i]) * (Js[i] + F[i]), f2 += F[i] * F[i];
      std::fprintf(stderr, "   last zone end step %.3g (scaled; width %.3g) first coeff step %.3g; F end row %.3g, (J s + F) end row %.3g; lin res %.3g of %.3g\n", lv.free_ends ? step[lv.at] : 0.0, 2 * lv.end_scale, step[lv.at + lv.free_ends], 0.0, 0.0, std::sqrt(r2), std::sqrt(f2));
    }
    // A step below the unknowns' rounding changes nothing: the residual is at its floor.
    if (result.residual < 1e-9 && norm(step) < 1e-13) {
      result.outcome = Outcome::converged;
      result.configuration = c;
      return result;
    }
    // Damping: every stretch between consecutive ends keeps a tenth of its length; a step
    // that would close one twice running is an event.
    const Configuration full = unpack([&] {
      std::vector<double> Xs = X;
      for (std::size_t i = 0; i < X.size(); ++i) Xs[i] += step[i];
      return Xs;
    }(), L);
    std::vector<double> ends{0}, moved{0};
    for (std::size_t k = 0; k < c.zones.size(); ++k) {
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
      if (std::getenv("WC_COUNT")) {
        std::size_t arg = 0; for (std::size_t i = 0; i < F_next.size(); ++i) if (std::fabs(F_next[i]) > std::fabs(F_next[arg])) arg = i;
        std::size_t zk = 0; for (std::size_t k = 0; k < L.zones.size(); ++k) if (L.zones[k].at <= arg) zk = k;
        std::fprintf(stderr, "      lambda %.3g merit %.4g -> %.4g (limited by stretch %zu) worst %.3g row %zu of zone %zu [%.9g %.9g] -> [%.9g %.9g]\n", lambda, merit, squares(F_next), limiting, F_next[arg], arg - L.zones[zk].at, zk, c.zones[zk].geometry.a, c.zones[zk].geometry.b, c_next.zones[zk].geometry.a, c_next.zones[zk].geometry.b);
      }
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
