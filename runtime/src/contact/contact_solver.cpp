#include "contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <string>

#include "active_set.hpp"
#include "chebyshev.hpp"
#include "constants.hpp"
#include "cosine_transform.hpp"
#include "grid_seed.hpp"
#include "support/validate.hpp"
#include "trace.hpp"
#include "verification.hpp"
#include "wavecontact/errors.hpp"
#include "zone_field.hpp"
#include "zone_system.hpp"

namespace wavecontact::detail {

namespace {

constexpr int most_changes = 400;               // changes of zones in one attempt
constexpr int quick_changes = 4;                // from one zone at the top, or from the previous loads
constexpr int most_resettles = 3;               // after a refined contact is refused
constexpr double max_single_zone_harmonic = 8;  // the highest harmonic of a surface tried so
// The largest step of a sweep, relative to the load before it, that starts from the contacts
// at the loads before (nearby_start). On 100-load lines (pa/p* 0.01 to 1, n = 32, H2 0.002
// and 0.02) such a start took 0.13 and 0.40 s against 0.45 and 0.68 s from the grid; on the
// short campaign's six loads from 0.01 to full contact, 4.0 s against 1.0 s (one sweep of
// 36 zones 11.8 s, settling through every zone a step opened). Any bound from 0.05 to 0.5 kept
// both at their best. At 0.5 the bench's map of 10^4 points took 3 % less time (its lines'
// third and fourth loads from the loads before), but 200 campaign sweeps of 20 loads (seed
// 5, steps of 30 to 60 %) took 323 s instead of 317 s, three of them 1.4 to 5 times as long.
// Bridging a larger step by unreported loads a quarter or a fifth apart, each settled from the
// ones before, took 0 and 2 % off that map (at a fifth, 502 grid seeds instead of 631): at the
// first loads of a line new zones appear faster than a few changes settle them.
constexpr double nearby_step = 0.25;

// Whether a zone's series d_j = j G_j / h (j >= 1), of `count` terms from the transform G of its
// right-hand side, is resolved: its last two terms below 1e-15 of sum |d_j|, or below the
// rounding they carry, count eps sum |G_j| / h (each G_j errs by about eps of the values, and
// d_j by j times that). Beyond, more nodes add only rounding: full contact of a roughness of
// n = 32, resolved at 72 nodes, went on doubling to the cap of 4096 (its tail at 5e-15 to
// 3e-14 all the way), and the pressure's error grew to 1e-12 of its largest (contact_test).
bool series_resolved(const std::vector<double>& d, const std::vector<double>& G, double h) {
  const std::size_t count = d.size();
  double magnitude = 0, transform = 0;
  for (std::size_t j = 1; j < count; ++j) magnitude += std::fabs(d[j]), transform += std::fabs(G[j]);
  const double tail = std::fabs(d[count - 1]) + std::fabs(d[count - 2]);
  const double rounding = static_cast<double>(count) * std::numeric_limits<double>::epsilon() * transform / h;
  return tail <= std::max(1e-15 * magnitude, rounding);
}

}  // namespace

ContactSolver::ContactSolver(std::shared_ptr<const SurfaceModel> surface, double tolerance, int nodes,
                             WorkBudget budget)
    : surface_(std::move(surface)), tolerance_(tolerance), fixed_nodes_(nodes), budget_(std::move(budget)) {
  // Full contact at P = 0: p0 = sum_{j>=1} d_j cos(j x^) (and a kink's part), the onset
  // -2 pi min p0. Sampled on a grid of at least 8 points a shortest wavelength by one cosine transform,
  // every local minimum refined.
  const ContactSolution full(surface_, full_contact_configuration(0, 0));
  const std::vector<double>& d = full.configuration().zones[0].d;
  std::size_t samples = 256;
  while (samples < 8 * pi / surface_->resolution || samples + 1 < d.size()) samples *= 2;
  std::vector<double> ps = cosine_series_on_grid(d, samples), xs(samples + 1);
  for (std::size_t i = 0; i <= samples; ++i) {
    xs[i] = pi * static_cast<double>(i) / static_cast<double>(samples);
    ps[i] += full.kink_pressure(0, xs[i]);
  }
  // Only the wells sampled within a tenth of the range of the lowest can hold the minimum:
  // at eight samples a shortest wavelength, a sample misses a well's bottom by about
  // 1 - cos(pi/8), 8 % of its depth, at most.
  const auto [low, high] = std::minmax_element(ps.begin(), ps.end());
  double lowest = std::numeric_limits<double>::infinity();
  const BatchFunction pressures = [&](const double* at, double* values, std::size_t count) {
    full.pressures(at, values, count);
  };
  for (const auto& [x, p] : local_minima(xs, ps, pressures, *low + 0.1 * (*high - *low))) {
    lowest = std::min(lowest, p);
  }
  onset_ = std::max(0.0, -2 * pi * lowest);
}

double ContactSolver::full_contact_load() const { return onset_; }

void ContactSolver::check_budget(double residual) const {
  if (residual < lowest_residual_) lowest_residual_ = residual;  // NaN compares false
  budget_.check([&] {
    char text[96];
    std::string where = "solving at P = " + format(target_load_) + ", the last attempt from " +
                        std::to_string(zones_tried_) + (zones_tried_ == 1 ? " zone" : " zones") + " in half a period";
    if (std::isfinite(lowest_residual_)) {
      std::snprintf(text, sizeof text, "; the lowest scaled residual Newton's method reached: %.3g", lowest_residual_);
      where += text;
    }
    return where;
  });
}

Configuration ContactSolver::full_contact_configuration(double P, int nodes) const {
  // One zone [0, pi] (h = 1, m = 0): d_j = j G_j (j >= 1) from (E/2) y, d_0 = P / (2 pi),
  // C = log(2) d_0 - G_0; the nodes grow until the series is resolved.
  const double half_E = surface_->E / 2;
  int count = nodes > 0 ? nodes : std::max(working_nodes, static_cast<int>(2 * pi / surface_->resolution) + 8);
  const ZoneGeometry g(0, pi);
  const double window = KinkCorrection::radius_for(*surface_, g);
  const std::shared_ptr<const KinkCorrection> kink = KinkCorrection::of(*surface_, g, window);
  for (;;) {
    const std::vector<double> x = g.angles_of(chebyshev::nodes(count));
    std::vector<double> values(x.size()), G(static_cast<std::size_t>(count)), kink_potential(kink ? x.size() : 0);
    surface_->height_differences(x.data(), x.size(), surface_->top_angle, values.data());
    if (kink) kink->potentials(x.data(), x.size(), kink_potential.data());
    for (std::size_t i = 0; i < x.size(); ++i) values[i] = half_E * values[i] - (kink ? kink_potential[i] : 0.0);
    chebyshev::coefficients(values.data(), count, G.data());
    Configuration c;
    ZoneUnknowns z{g, std::vector<double>(static_cast<std::size_t>(count)), window};
    z.d[0] = (P / 2 - (kink ? kink->load() : 0.0)) / pi;  // P / 2 = pi d_0 + the correction's
    for (int j = 1; j < count; ++j) z.d[static_cast<std::size_t>(j)] = j * G[static_cast<std::size_t>(j)];
    c.C = std::log(2.0) * z.d[0] - G[0];
    const bool resolved = series_resolved(z.d, G, 1);
    c.zones.push_back(std::move(z));
    if (nodes > 0 || resolved || count >= most_nodes) return c;
    count = std::min(most_nodes, count * 2);
  }
}

SolvedContact ContactSolver::full_contact(double P) const {
  Configuration c = full_contact_configuration(P, fixed_nodes_);
  const int nodes = static_cast<int>(c.zones[0].d.size());
  return {std::make_shared<const ContactSolution>(surface_, std::move(c)), P, 0.0, 0.0, nodes};
}

std::optional<Configuration> ContactSolver::single_zone(double P) const {
  // Tried on a surface without short wavelengths (a waviness alone), at its top.
  if (surface_->top_angle != 0 || surface_->resolution < pi / max_single_zone_harmonic) return std::nullopt;
  // Westergaard's sine of the top's curvature: P = pi E* kappa sin^2(a/2) (Hertz's for small
  // a), taken when a few changes of zones settle it. It knows the top alone: across a kink
  // (the slope's jump at b1/2 of the wave curve m > 0) the guess is kept short of it, and where
  // the load is beyond its reach (0.8 pi otherwise), a kinked surface takes the grid's seed.
  // The flat top m = 10 at n = 8 guessed 0.8 pi, a zone across the kink that crept and failed
  // on 296 nodes before the grid's seed found one zone short of it: a Python loop of 500
  // contacts there 5.5 -> 1.3 ms a point (m = 2: 3.5 -> 2.4); from a fresh process (H2 = 0.03)
  // pa/p* = 0.5, 1, 2 took 12.9, 12.5, 16.2 ms before and 14.2, 13.4, 13.8 after (2026-11-29).
  const double ratio = P / (pi * surface_->E * surface_->top_curvature);
  if (ratio >= 0.9 && !surface_->kinks.empty()) return std::nullopt;
  double w = ratio < 0.9 ? 2 * std::asin(std::sqrt(ratio)) : 0.8 * pi;
  for (const Kink& kink : surface_->kinks) w = std::min(w, 0.97 * kink.angle);
  Configuration c;
  c.zones.push_back({ZoneGeometry(0, w), std::vector<double>(working_nodes, 0.0)});
  const ZoneSystem system(*surface_, P);
  for (int i = 0; i < 3; ++i) system.relax(c);
  zones_tried_ = 1;
  return settle(surface_, P, std::move(c), {quick_changes, true}, [&](double residual) { check_budget(residual); })
      .contact;
}

LoadContact ContactSolver::settle_at(double P, const LoadContact* previous, const LoadContact* before) const {
  std::string failures;
  bool met_narrow_gap = false;
  const auto attempt = [&](const char* from, Configuration guess, SettleLimits limits) -> std::optional<Configuration> {
    zones_tried_ = guess.zones.size();
    trace_configuration(from, P, guess, "a guess");
    SettleOutcome s = settle(surface_, P, std::move(guess), limits, [&](double residual) { check_budget(residual); });
    if (!s.contact) failures += std::string(failures.empty() ? "" : "; ") + "from " + from + ": " + s.failure;
    met_narrow_gap = met_narrow_gap || s.met_narrow_gap;
    return std::move(s.contact);
  };
  // In a sweep of small steps the previous loads' contacts, extrapolated, are nearly this
  // one's, and a few changes of zones settle them; after a large step, or where the zones
  // change faster than the steps follow (the last load reached from the grid's seed, with
  // other zones than the load before it), the grid's seed. On a dense sweep of fine roughness
  // (campaign seed 11, sweep 82 with 60 loads, n = 236 and 996) that took 12 s, trying the
  // previous loads first at every load 26 s.
  if (previous && P - previous->P <= nearby_step * previous->P &&
      (!before || previous->continued || same_zones(before->contact, previous->contact))) {
    if (std::optional<Configuration> c = attempt(
            "the previous loads' contacts", nearby_start(*surface_, P, *previous, before), {quick_changes, true})) {
      return {P, std::move(*c), true, met_narrow_gap};
    }
  }
  if (std::optional<Configuration> c = single_zone(P)) return {P, std::move(*c)};
  // From the grid's seed, then a finer grid's. Where an attempt failed after meeting a tension
  // whose gap would be far narrower than the resolution (a gap about to close beside a long
  // zone, too narrow for its nodes as two zones), the same seed again with such gaps held as
  // the inner solutions of the merged zone's tension (narrow_gap.hpp).
  const int cells = seed_cells(*surface_);
  bool narrow_tried = false;
  for (const auto& [from, refined] : {std::pair{"the grid's contact", 1}, std::pair{"a finer grid's contact", 2}}) {
    Configuration seed = grid_seed(*surface_, P, refined * cells, working_nodes);
    if (std::optional<Configuration> c = attempt(from, seed, {most_changes}))
      return {P, std::move(*c), false, met_narrow_gap};
    if (met_narrow_gap && !narrow_tried) {
      narrow_tried = true;
      if (std::optional<Configuration> c =
              attempt("the same with narrow gaps", std::move(seed), {most_changes, false, true})) {
        return {P, std::move(*c)};
      }
    }
  }
  throw BeyondReach("wavecontact::solve_contact: no contact found at P = " + format(P) + " (" + failures + ")");
}

std::vector<SolvedContact> ContactSolver::solve(const std::vector<double>& loads) const {
  std::vector<std::size_t> order(loads.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return loads[a] < loads[b]; });
  std::vector<SolvedContact> solved(loads.size());
  std::optional<LoadContact> previous, before;
  for (std::size_t index : order) {
    const double P = loads[index];
    target_load_ = P;
    budget_.restart();
    lowest_residual_ = std::numeric_limits<double>::infinity();
    if (P >= onset_) {
      // Verified like every contact returned: should the onset's samples have missed the
      // deepest well's bottom, the tension sends this load to the zones' solver.
      SolvedContact full = full_contact(P);
      if (verify(*full.solution, gap_tolerance * surface_->height_range, pressure_tolerance).pressure_ok) {
        solved[index] = std::move(full);
        continue;
      }
    }
    const Checkpoint checkpoint = [&](double residual) { check_budget(residual); };
    LoadContact settled = settle_at(P, previous ? &*previous : nullptr, before ? &*before : nullptr);
    // A contact that its finer nodes refuse (a tension or a penetration that the working nodes
    // did not show) settles again from the refined configuration. Where the settling had met a
    // tension that narrow gaps would hold, the grid's seed settles with them first, on the
    // working nodes: campaign seed 46, sweep 134 (m = 0, n = 710, 624 and 416 at P = 2.5042)
    // had settled two zones beside a gap of 1e-5 in x^ instead, whose refinement's change grew
    // (2056 and 2284 nodes) and whose refined contact had a tension; settling again from that
    // took 32 s and failed, while the narrow gaps settle in 0.1 s. Whichever follows replaces
    // `settled` with a contact whose met_narrow_gap is clear, so this runs once a load.
    const auto with_narrow_gaps = [&]() {
      return settle(surface_, P, grid_seed(*surface_, P, seed_cells(*surface_), working_nodes),
                    {most_changes, false, true}, checkpoint);
    };
    for (int again = 0;; ++again) {
      Refinement r = refine(surface_, settled.contact, P, tolerance_, fixed_nodes_, checkpoint);
      // A contact refined above the tolerance where narrow gaps would hold a tension the
      // settling met: the contact with them instead, if it settles and its estimate is the
      // lower. Campaign seed 52, sweep 45 with 60 loads (m = 0.687, n = 40 at P = 1.3068) had
      // two zones 8e-5 apart in x^, refined to 3.8e-9 at the tolerance 1e-10 (their ends
      // scatter by a few 1e-9 with the path that solves them); with the gap as the merged
      // zone's narrow gap, 3.2e-12. Out of reach (its Newton's method failing, or the work
      // budget spent), the contact refined stands, with its estimate.
      if (r.solved && r.solved->error_estimate > tolerance_ && settled.met_narrow_gap &&
          r.solved->solution->configuration().narrow_gaps.empty()) {
        try {
          if (SettleOutcome s = with_narrow_gaps(); s.contact) {
            LoadContact narrow{P, std::move(*s.contact)};
            Refinement other = refine(surface_, narrow.contact, P, tolerance_, fixed_nodes_, checkpoint);
            if (other.solved && other.solved->error_estimate < r.solved->error_estimate) {
              r = std::move(other);
              settled = std::move(narrow);  // the next load continues from it
            }
          }
        } catch (const BeyondReach&) {
        }
      }
      if (r.solved) {
        solved[index] = std::move(*r.solved);
        break;
      }
      if (again == most_resettles) throw BeyondReach(r.refusal);
      const bool narrow = !r.refused.narrow_gaps.empty();
      if (!narrow && settled.met_narrow_gap) {
        if (SettleOutcome s = with_narrow_gaps(); s.contact) {
          settled = {P, std::move(*s.contact)};
          continue;
        }
      }
      SettleOutcome s = settle(surface_, P, std::move(r.refused), {most_changes, false, narrow}, checkpoint);
      if (!s.contact) throw BeyondReach(r.refusal + "; settled again from it: " + s.failure);
      settled = {P, std::move(*s.contact)};
    }
    before = std::move(previous);
    previous = std::move(settled);
  }
  return solved;
}

SingleZoneResult check_single_zone(const std::shared_ptr<const SurfaceModel>& surface, double a) {
  // One zone [0, a^] alone: its coefficients d_j = j G_j / h (j >= 1) from the transform of
  // (E/2) y, d_0 from the condition at a^ (bounded), C from the T_0 row; the nodes grow until
  // the series is resolved.
  const ZoneGeometry g(0, a);
  int count = working_nodes;
  Configuration c;
  for (;;) {
    const std::vector<double> x = g.angles_of(chebyshev::nodes(count));
    const double window = KinkCorrection::radius_for(*surface, g);
    const std::shared_ptr<const KinkCorrection> kink = KinkCorrection::of(*surface, g, window);
    const std::vector<double> G = right_hand_side(*surface, g, x, {}, kink.get());
    ZoneUnknowns z{g, std::vector<double>(static_cast<std::size_t>(count)), window};
    double alternating = 0;
    for (int j = 1; j < count; ++j) {
      z.d[static_cast<std::size_t>(j)] = j * G[static_cast<std::size_t>(j)] / g.h;
      alternating += (j % 2 == 0 ? 1 : -1) * z.d[static_cast<std::size_t>(j)];
    }
    z.d[0] = -alternating;  // sum_j (-1)^j d_j = 0 at tau = -1 (x^ = a)
    c.C = g.h * self_logarithm(g) * z.d[0] - G[0];
    const bool resolved = series_resolved(z.d, G, g.h);
    c.zones = {std::move(z)};
    if (resolved || count >= most_nodes) break;
    count = std::min(most_nodes, 2 * count);
  }
  const ContactSolution solution(surface, c);
  const double range = surface->height_range;
  const Verification v = verify(solution, gap_tolerance * range, pressure_tolerance);
  const bool penetrates = v.lowest_gap < -gap_tolerance * range;
  return {v.pressure_ok && !penetrates, penetrates, v.lowest_gap, v.x_of_lowest_gap, v.lowest_pressure,
          v.x_of_lowest_pressure};
}

}  // namespace wavecontact::detail
