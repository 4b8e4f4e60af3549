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

// The steps of the forward differences that form the Jacobian's products, relative to the
// product vector's largest entry. A difference errs by its step times the residual's
// curvature and by the residual's rounding (1e-12 to 1e-11) over the step. Where two zones
// nearly touch, the gap's width barely moves the residual and rounding dominates: at 1e-7
// Newton's steps went astray at a residual of 1e-8 until the work budget ran out (campaign
// sweep 1957), and 1e-6, near the root of the rounding, mends it. Where a kink's correction
// window curves the residual the step's own error dominates instead: the wave curve m = 10
// near full contact stalled at 2e-8 with 1e-6 and converged with 1e-7. Newton starts with
// the coarse step and changes to the other whenever a step fails to lower the residual.
constexpr double coarse_difference_step = 1e-6;
constexpr double fine_difference_step = 1e-7;

// The row of the largest residual, by zone, on stderr.
void trace_iteration(int iteration, double residual, const std::vector<double>& F, const SystemLayout& L) {
  const std::size_t row = static_cast<std::size_t>(
      std::max_element(F.begin(), F.end(), [](double u, double v) { return std::fabs(u) < std::fabs(v); }) - F.begin());
  std::size_t zone = 0;
  while (zone + 1 < L.zones.size() && L.zones[zone + 1].at <= row) ++zone;
  std::fprintf(stderr, "wavecontact trace:   iteration %d: residual %.3g (row %zu of zone %zu of %zu)\n", iteration,
               residual, row - (L.zones.empty() ? 0 : L.zones[zone].at), zone, L.zones.size());
}

// The damping of a Newton step: the largest fraction lambda <= 1 of it with which every
// stretch between consecutive ends of [0, a_1, b_1, ..., pi] keeps a tenth of its length in
// s, the stretch that limits it, and that stretch's length in x^ and its shrink under the
// full step (the same fraction of it as in s).
struct Damping {
  double lambda = 1;
  std::size_t limiting = 0;
  double length = 0, shrink = 0;
  bool overshoots() const { return lambda < 1 && shrink >= length; }  // the full step closes it
};

// An end as the unknowns hold it (SystemLayout): its distance 1 - s from the top (upper) or
// 1 + s from the valley, which a Newton step moves linearly, past the top or the valley too.
// (In x^ the motion is not linear, and a step that sends ends past the top is cut there: the
// damping of the whole step, reckoned in x^ from such ends, let two ends next to the top
// cross at a fraction of it, the residual of the crossed zones was not a number, and no
// contact was found (campaign seed 2, sweep 160 with 12 loads).)
struct EndPlace {
  bool upper = true;
  double distance = 0;
};

EndPlace fixed_end(double x) { return {x <= pi / 2, end_distance(x, x <= pi / 2)}; }

// s(left) - s(right), from the distances without cancellation when both are in one half.
double s_difference(const EndPlace& left, const EndPlace& right) {
  if (left.upper && right.upper) return right.distance - left.distance;
  if (!left.upper && !right.upper) return left.distance - right.distance;
  const auto s = [](const EndPlace& e) { return e.upper ? 1 - e.distance : e.distance - 1; };
  return s(left) - s(right);
}

Damping damping(const Configuration& now, const SystemLayout& L, const std::vector<double>& X,
                const std::vector<double>& step) {
  std::vector<EndPlace> ends{{true, 0}}, moved{{true, 0}};
  std::vector<double> angles{0};
  for (std::size_t k = 0; k < L.zones.size(); ++k) {
    const SystemLayout::Zone& lz = L.zones[k];
    std::size_t i = lz.at;
    const auto place = [&](bool free, bool upper, double x) {
      if (free) {
        ends.push_back({upper, X[i] * lz.end_scale}), moved.push_back({upper, (X[i] + step[i]) * lz.end_scale});
        ++i;
      } else {
        ends.push_back(fixed_end(x)), moved.push_back(ends.back());
      }
    };
    place(lz.a_free, lz.a_upper, lz.a);
    place(lz.b_free, lz.b_upper, lz.b);
    angles.push_back(now.zones[k].geometry.a), angles.push_back(now.zones[k].geometry.b);
  }
  ends.push_back({false, 0}), moved.push_back({false, 0});
  angles.push_back(pi);
  Damping d;
  double limiting_length = 0, limiting_shrink = 0;
  for (std::size_t e = 0; e + 1 < ends.size(); ++e) {
    const double length = s_difference(ends[e], ends[e + 1]);
    const double shrink = length - s_difference(moved[e], moved[e + 1]);
    if (length > 0 && shrink > 0 && d.lambda * shrink > 0.9 * length) {
      d.lambda = 0.9 * length / shrink, d.limiting = e;
      limiting_length = length, limiting_shrink = shrink;
    }
  }
  d.length = angles[d.limiting + 1] - angles[d.limiting];
  d.shrink = limiting_length > 0 ? d.length * limiting_shrink / limiting_length : 0.0;
  return d;
}

// The linear solve's relative tolerance for Newton's step at a point of largest scaled
// residual `residual`: it falls like the root of the residual, superlinear convergence without
// over-solving the first, far steps (Eisenstat and Walker); nor the last: a tenth of what takes
// the residual below Newton's `tolerance` is enough (0: no such bound). With every end held the
// equations are linear in the coefficients and C, and one step solved to that reaches the
// tolerance: the root's rule would only take more steps (on 100-load sweeps at n = 32, the
// consistent solves of settle took one Newton step instead of two, 22 % less time).
double forcing_term(const SystemLayout& L, double residual, double tolerance) {
  const bool linear =
      std::all_of(L.zones.begin(), L.zones.end(), [](const SystemLayout::Zone& z) { return z.free_ends == 0; });
  const double superlinear = linear ? 0.0 : 0.1 * std::sqrt(residual);
  return std::min(1e-2, std::max({1e-6, superlinear, 0.1 * tolerance / residual}));
}

}  // namespace

std::vector<double> ZoneSystem::linear_solve(const Linearisation& at, const std::vector<double>& rhs, double tolerance,
                                             double difference_step) const {
  const ZonePreconditioner preconditioner(surface_, at.c, at.layout, at.external_slope, P_);
  // A zone alone, without a kink correction: the preconditioner is the Jacobian itself (its
  // block, C and the load row, all exact), and its solve Newton's step; GMRES's products, each
  // a residual, would only confirm it (to their differences' error, 3e-7 at n = 8 and 32).
  const ZoneUnknowns& first = at.c.zones.front();
  if (at.c.zones.size() == 1 && !KinkCorrection::of(surface_, first.geometry, first.kink_window)) {
    return preconditioner.apply(rhs);
  }
  const auto jacobian_times = [&](const std::vector<double>& v) {
    const double size = largest(v);
    if (size == 0) return std::vector<double>(v.size(), 0.0);
    const double h = difference_step / size;
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
  for (ZoneUnknowns& z : start.zones) z.kink_window = fitting_window(z.geometry, z.kink_window);
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
  std::optional<Configuration> lowest_corrected;    // it moved by its Newton step
  int stalled = 0;                                  // iterations without halving the best residual
  bool coarse_steps = true;                         // linear solves no finer than the tolerance needs (forcing_term)
  double difference_step = coarse_difference_step;  // of the Jacobian's products (linear_solve)
  for (int iteration = 0; iteration < 40; ++iteration) {
    result.iterations = iteration;
    result.residual = largest(at.F);
    if (checkpoint) checkpoint(result.residual);
    if (!(result.residual < std::numeric_limits<double>::infinity())) {
      // Not a number: the iterate is no configuration to go on from; the lowest one is.
      if (lowest_residual < std::numeric_limits<double>::infinity()) {
        at.c = std::move(lowest);
        result.residual = lowest_residual;
      }
      return finish(Outcome::failed);
    }
    if (tracing()) trace_iteration(iteration, result.residual, at.F, L);
    if (result.residual < tolerance) return finish(Outcome::converged);
    if (result.residual < lowest_residual) lowest = at.c, lowest_residual = result.residual;
    if (result.residual < 0.5 * best) {
      best = result.residual, stalled = 0;
    } else if (++stalled >= (best < rounding_reached ? 1 : 8)) {
      // No progress: rounding reached (a profile's heights carry their own), or failed. The
      // best iterate is the result.
      at.c = std::move(lowest);
      result.residual = lowest_residual;
      result.corrected = std::move(lowest_corrected);
      return finish(lowest_residual < 1e-8 ? Outcome::converged : Outcome::failed);
    }
    const double forcing = forcing_term(L, result.residual, coarse_steps ? tolerance : 0.0);
    const std::vector<double> step = newton_step(at, forcing, difference_step);
    if (result.residual == lowest_residual) lowest_corrected = unpack(plus(at.X, 1, step), L);  // `at` is the lowest
    // A step below the unknowns' rounding changes nothing: the residual is at its floor.
    if (result.residual < 1e-9 && largest(step) < 1e-13) {
      result.corrected = unpack(plus(at.X, 1, step), L);
      return finish(Outcome::converged);
    }
    // Damping: every stretch between consecutive ends keeps a tenth of its length.
    const Damping damped = damping(at.c, L, at.X, step);
    // A full step that would close the stretch twice running within a thousandth of a
    // resolution, or a stretch already next to nothing, is an event: a gap between zones
    // closing, a zone reaching the top or the valley, or a zone vanishing. (Within a whole
    // resolution, gaps that stay open but narrow, as between the pieces of a zone cut at a
    // tension, were closed, and the cut undone, until the changes ran out.)
    const double near = 1e-3 * surface_.resolution;
    if ((damped.overshoots() && closing == damped.limiting && damped.length < near) ||
        (damped.lambda < 1 && damped.length - damped.lambda * damped.shrink < 1e-9 * pi)) {
      result.stretch = damped.limiting;
      return finish(Outcome::stretch_closes);
    }
    closing = damped.overshoots() ? damped.limiting : std::numeric_limits<std::size_t>::max();
    Linearisation next = backtrack(at, step, damped.lambda, result.residual < rounding_reached);
    // A step cut far may be one whose coefficients' part the ends' motion spoils: each zone's
    // nodes move with its ends, and next to a kink the rows curve with them (campaign seed 3,
    // sweep 69 with 16 loads: the full step met the end rows to 1e-13, the collocation rows
    // erred by 7e-4 lambda^2, and Newton's method crept in steps of 1/16 to 1/32 for 93
    // iterations). The ends' step with the coefficients solved for there is taken instead
    // where it lowers both the largest residual and the 2-norm (there, 8 iterations).
    if (next.step < 0x1p-3 && damped.lambda == 1 && !ends_fixed && result.residual >= rounding_reached) {
      Linearisation other = eliminated(at, step, forcing, difference_step);
      const double other_largest = largest(other.F), other_squares = squares(other.F);
      const bool better = other_largest < std::min(result.residual, largest(next.F)) &&
                          other_squares < std::min(squares(at.F), squares(next.F));
      if (tracing()) {
        std::fprintf(stderr, "wavecontact trace:     the ends' step, coefficients solved anew: residual %.3g (%s)\n",
                     other_largest, better ? "taken" : "not taken");
      }
      if (better) next = std::move(other);
    }
    // A step that had to be cut far may be one the coarse linear solve spoiled: from then on
    // the linear solves go to the forcing term alone.
    if (next.step < 0x1p-3) coarse_steps = false;
    // A step along which the residual did not fall at all came from products that erred more
    // than the step itself: the other difference step from then on (see the constants).
    if (!next.descended) {
      difference_step = difference_step == coarse_difference_step ? fine_difference_step : coarse_difference_step;
    }
    if (tracing()) {
      std::fprintf(stderr, "wavecontact trace:     step %.3g of Newton's (stretch %zu limits to %.3g)\n", next.step,
                   damped.limiting, damped.lambda);
    }
    at = std::move(next);
  }
  result.residual = largest(at.F);
  return finish(Outcome::failed);
}

std::vector<double> ZoneSystem::newton_step(const Linearisation& at, double forcing, double difference_step) const {
  std::vector<double> minus_F(at.F.size());
  for (std::size_t i = 0; i < at.F.size(); ++i) minus_F[i] = -at.F[i];
  return linear_solve(at, minus_F, forcing, difference_step);
}

ZoneSystem::Linearisation ZoneSystem::backtrack(const Linearisation& at, const std::vector<double>& step, double lambda,
                                                bool at_rounding) const {
  // Halving while the residual's 2-norm grows (the merit function whose decrease a Newton
  // step guarantees; the largest residual need not fall with it). Within rounding, the merit
  // function's changes are rounding too: no backtracking.
  const double merit = squares(at.F);
  Linearisation next;
  for (int halving = 0;; ++halving, lambda /= 2) {
    next.layout = at.layout;
    next.X = plus(at.X, lambda, step);
    next.c = unpack(next.X, at.layout);
    next.F = residual(next.c, at.layout, &next.external_slope);
    next.step = lambda;
    next.descended = squares(next.F) < (1 - 1e-4 * lambda) * merit;
    if (next.descended || at_rounding || halving == 8) return next;
  }
}

ZoneSystem::Linearisation ZoneSystem::eliminated(const Linearisation& at, const std::vector<double>& step,
                                                 double forcing, double difference_step) const {
  // With the ends held the equations are linear: one linear solve solves them, here to the
  // step's own forcing term (the point is judged by its residual, as the step's points are).
  Linearisation next;
  next.layout = at.layout;
  next.c = unpack(plus(at.X, 1, step), at.layout);
  const Linearisation ends_held = linearise(next.c, true);
  // Where the step's ends give a residual that is not a number, nothing more is computed (the
  // point is not taken): GMRES would run through all its products (7 s on one step, a zone's
  // end 2e-4 past the kink, its window 1.6e-4, 4096 nodes, campaign seed 4, sweep 12 with 16
  // loads).
  if (!(largest(ends_held.F) < std::numeric_limits<double>::infinity())) {
    next.F.assign(at.F.size(), std::numeric_limits<double>::quiet_NaN());
    return next;
  }
  next.c = unpack(plus(ends_held.X, 1, newton_step(ends_held, forcing, difference_step)), ends_held.layout);
  next.X = pack(next.c, at.layout);
  next.F = residual(next.c, at.layout, &next.external_slope);
  return next;
}

void ZoneSystem::choose_windows(Configuration& c) const {
  for (ZoneUnknowns& z : c.zones) z.kink_window = KinkCorrection::radius_for(surface_, z.geometry);
}

Configuration ZoneSystem::perturbed(const Configuration& c, const std::vector<double>& shift) const {
  const Linearisation at = linearise(c, false);
  std::vector<double> rhs(at.F.size(), 0.0);
  for (std::size_t k = 0; k < at.layout.zones.size(); ++k) {
    rhs[at.layout.zones[k].at] = shift[k] / at.layout.zones[k].row_scale;  // the zone's T_0 row
  }
  return unpack(plus(at.X, 1, linear_solve(at, rhs, 1e-3, coarse_difference_step)), at.layout);
}

Configuration ZoneSystem::newton_corrected(const Configuration& c) const {
  const Linearisation at = linearise(c, false);
  return unpack(plus(at.X, 1, newton_step(at, 1e-2, coarse_difference_step)), at.layout);
}

}  // namespace wavecontact::detail
