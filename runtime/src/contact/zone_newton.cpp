// Newton's method on the zone system (zone_system.hpp): each linear system by GMRES,
// preconditioned by ZonePreconditioner, the Jacobian's products by a difference of residuals.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "constants.hpp"
#include "gmres.hpp"
#include "kink_correction.hpp"
#include "trace.hpp"
#include "zone_preconditioner.hpp"
#include "zone_system.hpp"

namespace wavecontact::detail {

namespace {

double largest(const std::vector<double>& v) {  // infinite if any is not a number
  double m = 0;
  for (double e : v) {
    if (!(std::fabs(e) <= m)) m = std::isnan(e) ? std::numeric_limits<double>::infinity() : std::fabs(e);
  }
  return m;
}

double squares(const std::vector<double>& v) {
  double sum = 0;
  for (double e : v) sum += e * e;
  return std::isnan(sum) ? std::numeric_limits<double>::infinity() : sum;
}

std::vector<double> plus(std::vector<double> x, double lambda, const std::vector<double>& step) {
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += lambda * step[i];
  return x;
}

// Below this scaled residual, rounding dominates the rows of many zones (about 1e-11 with
// a thousand): Newton's method stops at the first iteration that does not halve it.
constexpr double rounding_reached = 1e-10;

}  // namespace

std::vector<double> ZoneSystem::linear_solve(const Linearisation& at, const std::vector<double>& rhs,
                                             double tolerance) const {
  const ZonePreconditioner preconditioner(surface_, at.c, at.layout, at.external_slope, P_);
  const auto jacobian_times = [&](const std::vector<double>& v) {
    const double size = largest(v);
    if (size == 0) return std::vector<double>(v.size(), 0.0);
    const double h = 1e-7 / size;
    std::vector<double> F = residual(unpack(plus(at.X, h, v), at.layout), at.layout, nullptr);
    for (std::size_t i = 0; i < F.size(); ++i) F[i] = (F[i] - at.F[i]) / h;
    return F;
  };
  return gmres(
      jacobian_times, [&](const std::vector<double>& v) { return preconditioner.apply(v); }, rhs, tolerance, 60, 3);
}

ZoneSystem::Linearisation ZoneSystem::linearise(Configuration c, bool ends_fixed) const {
  Linearisation at;
  at.layout = layout(c, ends_fixed);
  at.X = pack(c, at.layout);
  at.F = residual(c, at.layout, &at.external_slope);
  at.c = std::move(c);
  return at;
}

ZoneSystem::Result ZoneSystem::newton(Configuration start, double tolerance, const Checkpoint& checkpoint,
                                      bool ends_fixed) const {
  Result result;
  // Each kink correction's window chosen for the zones as they start, and kept.
  for (ZoneUnknowns& z : start.zones) z.kink_window = KinkCorrection::radius_for(surface_, z.geometry);
  Linearisation at = linearise(std::move(start), ends_fixed);
  const SystemLayout& L = at.layout;
  const auto finish = [&](Outcome outcome) {
    result.outcome = outcome;
    result.configuration = std::move(at.c);
    return result;
  };
  std::size_t closing = std::numeric_limits<std::size_t>::max();
  double best = std::numeric_limits<double>::infinity();  // the last residual that halved the one before
  Configuration lowest;                                   // the iterate of the lowest residual so far
  double lowest_residual = std::numeric_limits<double>::infinity();
  int stalled = 0;  // iterations without halving the best residual
  for (int iteration = 0; iteration < 40; ++iteration) {
    result.iterations = iteration;
    result.residual = largest(at.F);
    if (checkpoint) checkpoint(result.residual);
    if (!(result.residual < std::numeric_limits<double>::infinity())) return finish(Outcome::failed);
    if (tracing()) {
      const std::size_t row = static_cast<std::size_t>(
          std::max_element(at.F.begin(), at.F.end(), [](double u, double v) { return std::fabs(u) < std::fabs(v); }) -
          at.F.begin());
      std::size_t zone = 0;
      while (zone + 1 < L.zones.size() && L.zones[zone + 1].at <= row) ++zone;
      std::fprintf(stderr, "wavecontact trace:   iteration %d: residual %.3g (row %zu of zone %zu of %zu)\n", iteration,
                   result.residual, row - (L.zones.empty() ? 0 : L.zones[zone].at), zone, L.zones.size());
    }
    if (result.residual < tolerance) return finish(Outcome::converged);
    if (result.residual < lowest_residual) lowest = at.c, lowest_residual = result.residual;
    if (result.residual < 0.5 * best) {
      best = result.residual, stalled = 0;
    } else if (++stalled >= (best < rounding_reached ? 1 : 8)) {
      // No progress: rounding reached (a profile's heights carry their own), or failed. The
      // best iterate is the result.
      at.c = std::move(lowest);
      result.residual = lowest_residual;
      return finish(lowest_residual < 1e-8 ? Outcome::converged : Outcome::failed);
    }
    // The linear solve's tolerance falls like the root of the residual: superlinear
    // convergence without over-solving the first, far steps (Eisenstat and Walker).
    std::vector<double> minus_F(at.F.size());
    for (std::size_t i = 0; i < at.F.size(); ++i) minus_F[i] = -at.F[i];
    const double forcing = std::min(1e-2, std::max(1e-6, 0.1 * std::sqrt(result.residual)));
    const std::vector<double> step = linear_solve(at, minus_F, forcing);
    // A step below the unknowns' rounding changes nothing: the residual is at its floor.
    if (result.residual < 1e-9 && largest(step) < 1e-13) return finish(Outcome::converged);
    // Damping: every stretch between consecutive ends keeps a tenth of its length.
    const Configuration full = unpack(plus(at.X, 1, step), L);
    std::vector<double> ends{0}, moved{0};
    for (std::size_t k = 0; k < at.c.zones.size(); ++k) {
      ends.push_back(at.c.zones[k].geometry.a), ends.push_back(at.c.zones[k].geometry.b);
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
    // A full step that would close the stretch twice running within a thousandth of a
    // resolution, or a stretch already next to nothing, is an event: a gap between zones
    // closing, a zone reaching the top or the valley, or a zone vanishing. (Within a whole
    // resolution, gaps that stay open but narrow, as between the pieces of a zone cut at a
    // tension, were closed, and the cut undone, until the changes ran out.)
    const double length = ends[limiting + 1] - ends[limiting];
    const double shrink = length - (moved[limiting + 1] - moved[limiting]);
    const bool overshoots = lambda < 1 && shrink >= length;
    const double near = 1e-3 * surface_.resolution;
    if ((overshoots && closing == limiting && length < near) || (lambda < 1 && length - lambda * shrink < 1e-9 * pi)) {
      result.stretch = limiting;
      return finish(Outcome::stretch_closes);
    }
    closing = overshoots ? limiting : std::numeric_limits<std::size_t>::max();
    const double lambda_limit = lambda;
    // Backtracking while the residual's 2-norm grows (the merit function whose decrease a
    // Newton step guarantees; the largest residual need not fall with it).
    const double merit = squares(at.F);
    Linearisation next;
    for (int halving = 0;; ++halving, lambda /= 2) {
      next.layout = L;
      next.X = plus(at.X, lambda, step);
      next.c = unpack(next.X, L);
      next.F = residual(next.c, L, &next.external_slope);
      // Within rounding, the merit function's changes are rounding too: no backtracking.
      if (squares(next.F) < (1 - 1e-4 * lambda) * merit || result.residual < rounding_reached || halving == 8) break;
    }
    if (tracing()) {
      std::fprintf(stderr, "wavecontact trace:     step %.3g of Newton's (stretch %zu limits to %.3g)\n", lambda,
                   limiting, lambda_limit);
    }
    at = std::move(next);
  }
  result.residual = largest(at.F);
  return finish(Outcome::failed);
}

Configuration ZoneSystem::perturbed(const Configuration& c, const std::vector<double>& shift) const {
  const Linearisation at = linearise(c, false);
  std::vector<double> rhs(at.F.size(), 0.0);
  for (std::size_t k = 0; k < at.layout.zones.size(); ++k) {
    rhs[at.layout.zones[k].at] = shift[k] / at.layout.zones[k].row_scale;  // the zone's T_0 row
  }
  return unpack(plus(at.X, 1, linear_solve(at, rhs, 1e-3)), at.layout);
}

}  // namespace wavecontact::detail
