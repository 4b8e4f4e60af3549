#include "refinement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "active_set.hpp"
#include "constants.hpp"
#include "trace.hpp"
#include "support/parallel.hpp"
#include "support/validate.hpp"
#include "verification.hpp"
#include "wavecontact/errors.hpp"
#include "zone_field.hpp"
#include "zone_system.hpp"

namespace wavecontact::detail {

namespace {

// How far two solutions of one topology differ: the ends (to the period) and, on each zone,
// the pressure at the points that sample a's extrema (to the largest pressure), short of a
// hundredth of the zone from a free end (there the pressure goes like the root of the
// distance to the end, whose own difference is the first term): a's own samples of
// Span::inside, which the rounding's estimate takes again. A narrow gap's ends count as the
// zones'; one that only a holds or only b, by its width.
std::vector<double> zone_differences(const ContactSolution& a, const ContactSolution& b, double highest) {
  std::vector<double> difference(a.zone_count());
  for_each_index(a.zone_count(), zones_for_threads, [&](std::size_t k) {
    const ZoneGeometry& g = a.zone(k);
    double worst = std::max(std::fabs(g.a - b.zone(k).a), std::fabs(g.b - b.zone(k).b)) / pi;
    const std::vector<NarrowGap>&narrow_a = a.narrow_gaps(k), &narrow_b = b.narrow_gaps(k);
    if (narrow_a.size() == narrow_b.size()) {
      for (std::size_t i = 0; i < narrow_a.size(); ++i) {
        const double centre = std::fabs(narrow_a[i].centre - narrow_b[i].centre);
        worst = std::max(worst, (centre + std::fabs(narrow_a[i].half - narrow_b[i].half)) / pi);
      }
    } else {
      for (const NarrowGap& n : narrow_a.size() > narrow_b.size() ? narrow_a : narrow_b)
        worst = std::max(worst, 2 * n.half / pi);
    }
    const auto& [xs, pa] = a.sampled_pressure(k, ContactSolution::Span::inside);
    std::vector<double> pb(xs.size());
    b.pressures(xs.data(), pb.data(), xs.size());
    for (std::size_t i = 0; i < xs.size(); ++i) worst = std::max(worst, std::fabs(pa[i] - pb[i]) / highest);
    difference[k] = worst;
  });
  return difference;
}

// How far rounding moves the contact: the response to a shift of each zone's T_0 row by the
// rounding of the sum it comes from, |C| + (E/2)|y - y_top| + sum |Psi_l| (each |Psi_l| at
// most its coefficients' sum times its logarithm), with alternating signs; relative to the
// largest pressure, the ends to the period (as zone_differences).
double rounding_estimate(const std::shared_ptr<const SurfaceModel>& surface, const ZoneSystem& system,
                         const ContactSolution& solution, double highest) {
  const Configuration& c = solution.configuration();
  std::vector<double> magnitude;
  for (const ZoneUnknowns& z : c.zones) magnitude.push_back(own_potential(z));
  std::vector<double> shift(c.zones.size());
  for_each_index(c.zones.size(), zones_for_threads, [&](std::size_t k) {
    const ZoneGeometry& g = c.zones[k].geometry;
    const double s = std::cos((g.a + g.b) / 2);
    double terms = std::fabs(c.C) + surface->E / 2 * std::fabs(surface->depth((g.a + g.b) / 2));
    for (std::size_t l = 0; l < c.zones.size(); ++l) {
      if (l == k) continue;
      const ZoneGeometry& gl = c.zones[l].geometry;
      terms += magnitude[l] * (std::fabs(std::log(std::max(std::fabs(s - gl.m), gl.h))) + 1);
    }
    shift[k] = (k % 2 == 0 ? 1 : -1) * std::numeric_limits<double>::epsilon() * terms;
  });
  const std::vector<double> moved =
      zone_differences(solution, ContactSolution(surface, system.perturbed(c, shift)), highest);
  return moved.empty() ? 0.0 : *std::max_element(moved.begin(), moved.end());
}

// The largest of the zones' differences (zone_differences), infinite if one is not a number.
double largest_difference(const std::vector<double>& difference) {
  double worst = 0;
  for (double d : difference) worst = std::isnan(d) ? std::numeric_limits<double>::infinity() : std::max(worst, d);
  return worst;
}

// A solution moved by one more Newton step (ZoneSystem::newton_corrected, or the step Newton's
// method computed there), and how far that moves it, as the refinement measures its changes
// (to `highest`): Newton's error in it. (Its linear system solved to a tenth, the step of
// seed 52's sweep 45 below was a third of the true one.)
struct NewtonStep {
  double change = 0;
  std::shared_ptr<const ContactSolution> to;
};
NewtonStep newton_step(const std::shared_ptr<const SurfaceModel>& surface, const ContactSolution& from,
                       Configuration corrected, double highest) {
  auto to = std::make_shared<const ContactSolution>(surface, std::move(corrected));
  return {largest_difference(zone_differences(from, *to, highest)), std::move(to)};
}

// A solution of the refinement and Newton's error in it, where measured.
struct Polished {
  std::shared_ptr<const ContactSolution> solution;
  std::optional<double> newton_error;
};

// A solution corrected by Newton's steps (newton_step; the first given) as long as they move
// it by more than `looked_at` and by less than a quarter of the step before, and Newton's
// error in it. A step that does not fall by four has reached the rounding of the
// equations, and the steps then sample its response: the error is the larger of the last two.
// Beside a narrow gap that response is far above rounding_estimate's: seed 52's sweep 45 below
// (two zones 8e-5 apart in x^) at the tolerance 1e-8 was returned 8.5e-9 from the solution,
// where single steps from it measured 1.8e-9 or 8.9e-9 with the nodes (and two steps in a row
// on the working nodes 2.3e-8 and 2.5e-8).
Polished corrected(const std::shared_ptr<const SurfaceModel>& surface, const ZoneSystem& system,
                   std::shared_ptr<const ContactSolution> from, Configuration first, double highest, double looked_at) {
  NewtonStep next = newton_step(surface, *from, std::move(first), highest);
  Polished now{std::move(from), next.change};
  for (int step = 0; step < 3 && next.change > looked_at; ++step) {
    NewtonStep after = newton_step(surface, *next.to, system.newton_corrected(next.to->configuration()), highest);
    if (!(after.change < 0.25 * next.change)) {
      now.newton_error = std::max(next.change, after.change);
      break;
    }
    now = {std::move(next.to), after.change};
    next = std::move(after);
  }
  return now;
}

// Newton's method stops short of its tolerance where its residual reaches its rounding; below
// 1e-10, at the first iteration that does not halve it (zone_newton.cpp, rounding_reached).
// Next to a narrow gap, where the residual barely sees the ends' places, that left the ends
// 3.6e-7 from the solution at a residual of 2e-11 (seed 52, sweep 45 with 60 loads), at two
// node counts alike, whose change (8.1e-10) did not see it. Such a solution is corrected
// (corrected(), from the step Newton's method computed at it) while the steps are above a
// tenth of the tolerance. `highest`: the refinement's largest pressure, 0 for the solution's
// own.
Polished polished(const std::shared_ptr<const SurfaceModel>& surface, const ZoneSystem& system,
                  ZoneSystem::Result newton, double target, double highest, double tolerance) {
  auto solution = std::make_shared<const ContactSolution>(surface, std::move(newton.configuration));
  if (newton.residual < target) return {std::move(solution), std::nullopt};
  if (highest == 0) highest = highest_sampled_pressure(*solution);
  Configuration first =
      newton.corrected ? std::move(*newton.corrected) : system.newton_corrected(solution->configuration());
  return corrected(surface, system, std::move(solution), std::move(first), highest, 0.1 * tolerance);
}

}  // namespace

Refinement refine(const std::shared_ptr<const SurfaceModel>& surface, const Configuration& settled, double P,
                  double tolerance, int fixed_nodes, const Checkpoint& checkpoint) {
  // The nodes of each zone double until its pressure and ends change by less than half
  // the tolerance (or, fixed, are compared with half as many again); the error estimate is the
  // last change, that of the coarser solution: an upper bound while the series converge.
  const ZoneSystem system(*surface, P);
  const double range = surface->height_range;
  // Newton's tolerance: a thousandth of the error tolerated (a coefficient's error is at
  // most its index times its row's residual), within the residuals' rounding (about 1e-13
  // of each zone's own potential).
  const double residual = std::clamp(1e-3 * tolerance, 1e-13, 1e-10);
  const auto solve = [&](Configuration start) {
    system.relax(start);
    for (int attempt = 0;; ++attempt) {
      const ZoneSystem::Result r = system.newton(start, residual, checkpoint);
      if (r.outcome != ZoneSystem::Outcome::converged && !(r.residual < 1e-9)) {
        char residual_text[32];
        std::snprintf(residual_text, sizeof residual_text, "%.3g", r.residual);
        throw BeyondReach("wavecontact::solve_contact: Newton's method did not converge refining the contact at P = " +
                          format(P) + " (residual " + residual_text + ")");
      }
      if (system.windows_fit(r.configuration) || attempt == 2) return r;
      start = r.configuration;  // a kink window chosen again
    }
  };
  Configuration c = settled;
  if (fixed_nodes > 0) {
    for (ZoneUnknowns& z : c.zones) z.d.resize(static_cast<std::size_t>(fixed_nodes), 0.0);
  }
  // Each configuration's solution formed once: the differences, the verification and the
  // rounding share them.
  Polished first = polished(surface, system, solve(c), residual, 0.0, tolerance);
  std::shared_ptr<const ContactSolution> current = std::move(first.solution);
  std::optional<double> newton_error = first.newton_error;  // current's
  c = current->configuration();
  std::shared_ptr<const ContactSolution> coarser_solution;  // the last round's
  // A zone keeps doubling while its change is above half the tolerance and still falls
  // (by four at least: below, its rounding is reached), or while its kink window holds fewer
  // than least_window_nodes, where its change need not fall yet: a zone ending 8.4e-5 past
  // the kink (window 2.2e-5; m = 22.3 with n = 2, 4, 114 and 386 at P = 99.518, campaign seed
  // 97, sweep 9 with 16 loads) changed by 1.0e-8 and 1.9e-8 at 8192 and 16384 nodes (13 and
  // 26 in the window) and by 3.9e-10 at 32768 (51).
  std::vector<double> difference, previous(c.zones.size(), std::numeric_limits<double>::infinity());
  std::vector<bool> converging(c.zones.size(), true);
  const double highest = highest_sampled_pressure(*current);
  // A zone already at its most nodes cannot double: its estimate is its change from half as many.
  const auto most = [](const ZoneUnknowns& z) {
    return static_cast<std::size_t>(z.kink_window > 0 ? most_kinked_nodes : most_nodes);
  };
  double capped_change = 0;
  if (fixed_nodes == 0) {
    Configuration coarser = c;
    bool halved = false;
    for (ZoneUnknowns& z : coarser.zones) {
      if (z.d.size() >= most(z)) z.d.resize(z.d.size() / 2), halved = true;
    }
    if (halved) {
      const std::vector<double> change =
          zone_differences(ContactSolution(surface, solve(coarser).configuration), *current, highest);
      for (std::size_t k = 0; k < change.size(); ++k) {
        if (c.zones[k].d.size() >= most(c.zones[k])) capped_change = std::max(capped_change, change[k]);
      }
    }
  }
  for (int round = 0; round < 10; ++round) {
    Configuration finer = c;
    bool grown = false;
    for (std::size_t k = 0; k < finer.zones.size(); ++k) {
      const bool again = difference.empty() || (difference[k] > 0.5 * tolerance && converging[k]);
      const std::size_t n = finer.zones[k].d.size();
      const std::size_t target = fixed_nodes > 0 ? n + n / 2 : std::min(most(finer.zones[k]), 2 * n);
      if (again && target > n) finer.zones[k].d.resize(target, 0.0), grown = true;
    }
    if (!grown) break;
    Polished refined_polished = polished(surface, system, solve(finer), residual, highest, tolerance);
    std::shared_ptr<const ContactSolution> refined = std::move(refined_polished.solution);
    finer = refined->configuration();
    const std::vector<double> change = zone_differences(*current, *refined, highest);
    for (std::size_t k = 0; k < change.size(); ++k) {
      if (finer.zones[k].d.size() != c.zones[k].d.size()) {
        converging[k] = change[k] < 0.25 * previous[k] || window_unresolved(*surface, finer.zones[k]);
        previous[k] = change[k];
      }
    }
    difference = change;
    if (tracing()) {
      const double worst = *std::max_element(change.begin(), change.end());
      std::fprintf(stderr, "wavecontact trace: refined round %d: largest change %.3g\n", round, worst);
    }
    trace_configuration("refinement", P, finer, "a finer contact");
    if (fixed_nodes > 0) break;
    c = std::move(finer);
    coarser_solution = std::move(current);
    current = std::move(refined);
    newton_error = refined_polished.newton_error;
  }
  // Rounding moves the solution of the equations, whatever their nodes once they resolve it:
  // its response is taken on the last round's solution, which the result differs from by
  // less than the tolerance, with half the nodes (half the cost: on 100-load sweeps at
  // n = 32 the estimate took 17 % of the time; the error estimates reported stayed the same).
  const double rounding = rounding_estimate(surface, system, coarser_solution ? *coarser_solution : *current, highest);
  // Newton's error in the result, where Newton's method reached its tolerance too: there the
  // residual bounds it only as far as the equations' conditioning allows. A step above ten
  // times the rounding's response is looked at again, even below a tenth of the tolerance:
  // seed 52's sweep 45 at 3e-8 measured 1.8e-9 with one step, where the contact was 8.5e-9
  // from the solution. Not below a thousandth of it, where an error at the tolerance would
  // take a thousandfold magnification of the step (seed 52's: 4.7): at 1e-8, where Newton's
  // method stops at 1e-11 and its steps lie far above the rounding, the steps looked at
  // again took 10 % of a 10^4-point map's time (bench/map_vs_loops.py, 3.66 s against 3.31 s).
  if (!newton_error) {
    Polished last = corrected(surface, system, current, system.newton_corrected(current->configuration()), highest,
                              std::min(0.1 * tolerance, std::max(10 * rounding, 1e-3 * tolerance)));
    current = std::move(last.solution);
    newton_error = last.newton_error;
  }
  const Verification v = verify(*current, gap_tolerance * range, pressure_tolerance);
  double error =
      std::max(capped_change, difference.empty() ? 0.0 : *std::max_element(difference.begin(), difference.end()));
  // A narrow gap's inner solution errs by its own neglected terms, whatever the nodes.
  for (std::size_t k = 0; k < current->zone_count(); ++k) {
    const ZoneGeometry& g = current->zone(k);
    for (const NarrowGap& n : current->narrow_gaps(k)) {
      const double room = std::min(g.top() ? pi : n.centre - g.a, g.valley() ? pi : g.b - n.centre);
      error = std::max(error, n.error(room) / highest);
    }
  }
  int nodes = 0;
  for (const ZoneUnknowns& z : c.zones) nodes = std::max(nodes, static_cast<int>(z.d.size()));
  // Not a number: no estimate, and no error of the solution's own to admit gaps within.
  if (!(*newton_error < std::numeric_limits<double>::infinity())) {
    throw BeyondReach("wavecontact::solve_contact: Newton's step from the refined contact at P = " + format(P) +
                      " is not a number");
  }
  if (tracing()) {
    std::fprintf(stderr, "wavecontact trace: estimate: discretisation %.3g, Newton's %.3g, rounding %.3g\n", error,
                 *newton_error, rounding);
  }
  error = std::max(error, *newton_error);
  // Admissible within the error of the solution itself (a gap of the estimate's order next to
  // an end whose place is as uncertain).
  const double allowed = std::max(gap_tolerance, 10 * std::max(error, rounding)) * range;
  if (!v.pressure_ok || v.lowest_gap < -allowed) {
    char text[80];
    std::snprintf(text, sizeof text, " is not admissible (lowest pressure %.3g, lowest gap %.3g)", v.lowest_pressure,
                  v.lowest_gap);
    return {std::nullopt, std::move(c), "wavecontact::solve_contact: the refined contact at P = " + format(P) + text};
  }
  return {SolvedContact{std::move(current), P, std::max(error, rounding), rounding, nodes}, {}, {}};
}

}  // namespace wavecontact::detail
