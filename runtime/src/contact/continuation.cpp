#include "continuation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numeric>
#include <string>

#include <boost/math/tools/minima.hpp>

#include "chebyshev.hpp"
#include "constants.hpp"
#include "verification.hpp"
#include "zone_field.hpp"

namespace wavecontact::detail {

namespace {

constexpr int continuation_nodes = 16;     // Chebyshev nodes of a zone while continuing
constexpr double continuation_residual = 1e-11;
constexpr double final_residual = 1e-14;
constexpr double gap_tolerance = 1e-9;        // of the height range
constexpr double pressure_tolerance = 1e-9;   // of the largest pressure
constexpr int topology_changes = 64;
constexpr double smallest_step = 1e-9;
constexpr int most_nodes = 4096;
constexpr int most_continuation_nodes = 512;  // while continuing, the topology is what matters
constexpr double birth_width = 1.0 / 16;  // a new zone's half-width, of the resolution, at most
constexpr double continuation_tail = 1e-9;  // of a zone's coefficients: beyond, more nodes

// The part of a zone's coefficients the last three hold: how far its series is from converged.
double tail(const std::vector<double>& d) {
  double magnitude = 0;
  for (double v : d) magnitude += std::fabs(v);
  const std::size_t n = d.size();
  return (std::fabs(d[n - 1]) + std::fabs(d[n - 2]) + std::fabs(d[n - 3])) / std::max(magnitude, 1e-300);
}

// At least the nodes a zone's width asks for: four a half wavelength of the shortest harmonic
// on top of the 16 of a cap, so that the density of a zone that spans several asperities is
// resolved before Newton's method meets it.
void fit_nodes(Configuration& c, double resolution) {
  for (ZoneUnknowns& z : c.zones) {
    const double halves = (z.geometry.b - z.geometry.a) / resolution;
    const std::size_t needed = static_cast<std::size_t>(continuation_nodes + 8 * std::ceil(halves / 2));
    if (z.d.size() < needed) z.d.resize(std::min<std::size_t>(most_continuation_nodes, needed), 0.0);
  }
}

// Twice the nodes (at most `most`) for a zone whose tail exceeds `limit` (the rest keep
// theirs); whether any grew.
bool grow_nodes(Configuration& c, double limit, int most = most_continuation_nodes) {
  bool grown = false;
  for (ZoneUnknowns& z : c.zones) {
    if (tail(z.d) > limit && z.d.size() < static_cast<std::size_t>(most)) {
      z.d.resize(std::min<std::size_t>(static_cast<std::size_t>(most), 2 * z.d.size()), 0.0);
      grown = true;
    }
  }
  return grown;
}

// WAVECONTACT_TRACE=1 in the environment: every step of the continuation on stderr (a
// diagnostic for a stall: where it happened, what Newton's method did).
bool tracing() {
  static const bool on = [] {
    const char* value = std::getenv("WAVECONTACT_TRACE");
    return value != nullptr && *value != '\0' && *value != '0';
  }();
  return on;
}

void trace_configuration(const char* what, double P, const Configuration& c, const char* outcome) {
  if (!tracing()) return;
  std::fprintf(stderr, "wavecontact trace: %s P = %.9g: %s, %zu zone%s:", what, P, outcome, c.zones.size(),
               c.zones.size() == 1 ? "" : "s");
  for (const ZoneUnknowns& z : c.zones) std::fprintf(stderr, " [%.6g, %.6g]/%zu", z.geometry.a, z.geometry.b, z.d.size());
  std::fprintf(stderr, "\n");
}

// Every end of the zones in increasing x^, with 0 and pi around them.
std::vector<double> all_ends(const Configuration& c) {
  std::vector<double> ends{0};
  for (const ZoneUnknowns& z : c.zones) ends.push_back(z.geometry.a), ends.push_back(z.geometry.b);
  ends.push_back(pi);
  return ends;
}

bool same_topology(const Configuration& a, const Configuration& b) {
  if (a.zones.size() != b.zones.size()) return false;
  for (std::size_t k = 0; k < a.zones.size(); ++k) {
    if (a.zones[k].geometry.top() != b.zones[k].geometry.top() ||
        a.zones[k].geometry.valley() != b.zones[k].geometry.valley() ||
        a.zones[k].d.size() != b.zones[k].d.size()) {
      return false;
    }
  }
  return true;
}

ZoneUnknowns zone_of(double a, double b, std::size_t nodes) {
  return {ZoneGeometry(a, b), std::vector<double>(nodes, 0.0)};
}

}  // namespace

ContactSolver::ContactSolver(std::shared_ptr<const SurfaceModel> surface, double tolerance, int nodes, WorkBudget budget)
    : surface_(std::move(surface)), tolerance_(tolerance), fixed_nodes_(nodes), budget_(std::move(budget)) {
  top_angle_ = surface_->top_angle, top_curvature_ = surface_->top_curvature, height_range_ = surface_->height_range;
  // Full contact at P = 0: p0 = sum_{j>=1} d_j cos(j x^), the onset -2 pi min p0.
  const ContactSolution full(surface_, full_contact_configuration(0, 0));
  double lowest = std::numeric_limits<double>::infinity(), at = 0;
  const int samples = std::max(256, static_cast<int>(8 * pi / surface_->resolution));
  std::vector<double> xs, ps;
  for (int i = 0; i <= samples; ++i) xs.push_back(pi * i / samples), ps.push_back(full.pressure(xs.back()));
  for (const auto& [x, p] : local_minima(xs, ps, [&](double x) { return full.pressure(x); })) {
    if (p < lowest) lowest = p, at = x;
  }
  (void)at;
  onset_ = std::max(0.0, -2 * pi * lowest);
}

double ContactSolver::full_contact_load() const { return onset_; }

void ContactSolver::check_budget() const {
  budget_.check([&] {
    char text[96];
    std::snprintf(text, sizeof text, "the continuation reached P = %.6g of %.6g, ", reached_load_, target_load_);
    return text + std::to_string(reached_zones_) + (reached_zones_ == 1 ? " zone" : " zones") + " in half a period";
  });
}

Configuration ContactSolver::full_contact_configuration(double P, int nodes) const {
  // One zone [0, pi] (h = 1, m = 0): d_j = j G_j (j >= 1) from (E/2) y, d_0 = P / (2 pi),
  // C = log(2) d_0 - G_0; the nodes grow until the coefficients' tail is negligible.
  const double half_E = surface_->E / 2;
  int count = nodes > 0 ? nodes : std::max(continuation_nodes, static_cast<int>(2 * pi / surface_->resolution) + 8);
  for (;;) {
    const ZoneGeometry g(0, pi);
    const std::vector<double> x = g.angles_of(chebyshev::nodes(count));
    const std::shared_ptr<const KinkCorrection> kink = KinkCorrection::of(*surface_, g);
    std::vector<double> values, G(static_cast<std::size_t>(count));
    for (double xi : x) values.push_back(half_E * surface_->depth(xi) - (kink ? kink->potential(xi) : 0.0));
    chebyshev::coefficients(values.data(), count, G.data());
    Configuration c;
    ZoneUnknowns z{g, std::vector<double>(static_cast<std::size_t>(count))};
    z.d[0] = (P / 2 - (kink ? kink->load() : 0.0)) / pi;  // P / 2 = pi d_0 + the correction's
    double magnitude = 0;
    for (int j = 1; j < count; ++j) {
      z.d[static_cast<std::size_t>(j)] = j * G[static_cast<std::size_t>(j)];
      magnitude += std::fabs(z.d[static_cast<std::size_t>(j)]);
    }
    c.C = std::log(2.0) * z.d[0] - G[0];
    const double tail = std::fabs(z.d[static_cast<std::size_t>(count - 1)]) + std::fabs(z.d[static_cast<std::size_t>(count - 2)]);
    c.zones.push_back(std::move(z));
    if (nodes > 0 || tail <= 1e-15 * magnitude || count >= most_nodes) return c;
    count = std::min(most_nodes, count * 2);
  }
}

SolvedContact ContactSolver::full_contact(double P) const {
  Configuration c = full_contact_configuration(P, fixed_nodes_);
  const int nodes = static_cast<int>(c.zones[0].d.size());
  return {std::make_shared<const ContactSolution>(surface_, std::move(c)), P, 0.0, 0.0, nodes};
}

std::optional<ContactSolver::State> ContactSolver::settle(Configuration c, double P) const {
  const ZoneSystem system(*surface_, {true, P});
  for (int change = 0; change < topology_changes; ++change) {
    check_budget();
    fit_nodes(c, surface_->resolution);
    const ZoneSystem::Result r = system.newton(c, continuation_residual, [&] { check_budget(); });
    trace_configuration("newton at", P, r.configuration,
                        r.outcome == ZoneSystem::Outcome::converged ? "converged"
                        : r.outcome == ZoneSystem::Outcome::failed  ? "failed"
                                                                    : "a stretch closes");
    if (r.outcome == ZoneSystem::Outcome::converged) {
      c = r.configuration;
      if (!grow_nodes(c, continuation_tail)) return State{c, P};
      system.relax(c);
      continue;
    }
    if (r.outcome == ZoneSystem::Outcome::failed) {
      // A zone across a kink, too coarse for its density, may keep Newton from converging:
      // more nodes there, or give up.
      c = r.configuration;
      bool grown = false;
      for (ZoneUnknowns& z : c.zones) {
        const bool kinked = std::any_of(surface_->kinks.begin(), surface_->kinks.end(), [&](const Kink& k) {
          return k.angle > z.geometry.a && k.angle < z.geometry.b;
        });
        if (kinked && tail(z.d) > 1e-6 && z.d.size() < static_cast<std::size_t>(most_continuation_nodes)) {
          z.d.resize(2 * z.d.size(), 0.0), grown = true;
        }
      }
      if (!grown) return std::nullopt;
      system.relax(c);
      continue;
    }
    // A stretch closes: between ends e and e + 1 of [0, a_0, b_0, ..., pi].
    c = r.configuration;
    const std::size_t e = r.stretch, last = 2 * c.zones.size();
    if (e == 0) {
      c.zones.front().geometry = ZoneGeometry(0, c.zones.front().geometry.b);
    } else if (e == last) {
      c.zones.back().geometry = ZoneGeometry(c.zones.back().geometry.a, pi);
    } else if (e % 2 == 1) {  // zone (e - 1)/2 vanishes
      c.zones.erase(c.zones.begin() + static_cast<std::ptrdiff_t>((e - 1) / 2));
      if (c.zones.empty()) return std::nullopt;
    } else {  // the gap between zones e/2 - 1 and e/2 closes: they merge
      const std::size_t k = e / 2 - 1;
      const std::size_t nodes = std::max(c.zones[k].d.size(), c.zones[k + 1].d.size());
      const ZoneUnknowns merged = zone_of(c.zones[k].geometry.a, c.zones[k + 1].geometry.b, nodes);
      c.zones[k] = merged;
      c.zones.erase(c.zones.begin() + static_cast<std::ptrdiff_t>(k) + 1);
    }
    system.relax(c);
  }
  return std::nullopt;
}

ContactSolver::State ContactSolver::seed(double P) const {
  // A small zone at the highest point carrying at most P, its width from Hertz's contact of
  // a cylinder of the top's curvature (a^2 = 4 P / (pi E* kappa)).
  const double kappa = top_curvature_, E = surface_->E;
  double load = std::min(P, 1e-3 * pi * E * kappa * std::pow(std::min(0.05, surface_->resolution / 8), 2) / 4);
  for (int attempt = 0; attempt < 60; ++attempt, load /= 4) {
    const double w = std::sqrt(4 * load / (pi * E * kappa));
    Configuration c;
    if (top_angle_ < w) {
      c.zones.push_back(zone_of(0, w, continuation_nodes));
    } else if (top_angle_ > pi - w) {
      c.zones.push_back(zone_of(pi - w, pi, continuation_nodes));
    } else {
      c.zones.push_back(zone_of(top_angle_ - w, top_angle_ + w, continuation_nodes));
    }
    const ZoneSystem system(*surface_, {true, load});
    for (int i = 0; i < 3; ++i) system.relax(c);
    std::optional<State> s = settle(c, load);
    if (!s || s->c.zones.size() != 1) continue;
    const Verification v = verify(ContactSolution(surface_, s->c), gap_tolerance * height_range_, pressure_tolerance);
    if (v.pressure_ok && v.penetrations.empty()) return *s;
  }
  throw BeyondReach("wavecontact::solve_contact: no small contact zone at the highest point carries the load " +
                    std::to_string(P));
}

std::optional<ContactSolver::State> ContactSolver::single_zone(double P) const {
  if (top_angle_ != 0) return std::nullopt;
  // Westergaard's sine of the top's curvature: P = pi E* kappa sin^2(a/2) (Hertz's for small a).
  const double ratio = P / (pi * surface_->E * top_curvature_);
  const double w = ratio < 0.9 ? 2 * std::asin(std::sqrt(ratio)) : 0.8 * pi;
  Configuration c;
  c.zones.push_back(zone_of(0, w, continuation_nodes));
  const ZoneSystem system(*surface_, {true, P});
  for (int i = 0; i < 3; ++i) system.relax(c);
  // One zone at the top, with no event on the way (else the continuation finds the contact).
  std::optional<State> s;
  for (int round = 0; round < 8 && !s; ++round) {
    const ZoneSystem::Result r = system.newton(c, continuation_residual, [&] { check_budget(); });
    if (r.outcome != ZoneSystem::Outcome::converged || r.configuration.zones[0].geometry.valley()) return std::nullopt;
    c = r.configuration;
    if (!grow_nodes(c, continuation_tail)) s = State{c, P};
  }
  if (!s) return std::nullopt;
  const Verification v = verify(ContactSolution(surface_, s->c), gap_tolerance * height_range_, pressure_tolerance);
  if (!v.pressure_ok || !v.penetrations.empty()) return std::nullopt;
  return s;
}

std::optional<ContactSolver::State> ContactSolver::advance(const State& from, const State* before, double P) const {
  Configuration guess = from.c;
  if (before && same_topology(before->c, from.c) && from.P != before->P) {
    // Secant predictor: a zone's centre, C and the coefficients linear in the load, its
    // half-width squared (a zone just born widens like the root of the load beyond its birth).
    const double t = (P - from.P) / (from.P - before->P);
    bool ordered = true;
    for (std::size_t k = 0; k < guess.zones.size(); ++k) {
      const ZoneGeometry& g0 = before->c.zones[k].geometry;
      const ZoneGeometry& g1 = from.c.zones[k].geometry;
      double a = g1.a + t * (g1.a - g0.a), b = g1.b + t * (g1.b - g0.b);
      if (!g1.top() && !g1.valley()) {
        const double c0 = (g0.a + g0.b) / 2, c1 = (g1.a + g1.b) / 2, w0 = (g0.b - g0.a) / 2, w1 = (g1.b - g1.a) / 2;
        const double centre = c1 + t * (c1 - c0), squared = w1 * w1 + t * (w1 * w1 - w0 * w0);
        if (squared > 0) a = centre - std::sqrt(squared), b = centre + std::sqrt(squared);
      }
      if (g1.top()) a = 0;
      if (g1.valley()) b = pi;
      guess.zones[k].geometry = ZoneGeometry(a, b);
      for (std::size_t j = 0; j < guess.zones[k].d.size(); ++j) {
        guess.zones[k].d[j] += t * (from.c.zones[k].d[j] - before->c.zones[k].d[j]);
      }
    }
    guess.C += t * (from.c.C - before->c.C);
    const std::vector<double> ends = all_ends(guess);
    for (std::size_t i = 0; i + 1 < ends.size(); ++i) ordered = ordered && ends[i] < ends[i + 1];
    if (!ordered) guess = from.c;
  } else {
    // A zone opened on the way to `from` widens like the root of the load beyond its birth.
    for (ZoneUnknowns& z : guess.zones) {
      const ZoneGeometry& g = z.geometry;
      if (g.top() || g.valley() || !(z.birth_load >= 0 && from.P > z.birth_load)) continue;
      const double centre = (g.a + g.b) / 2, w = (g.b - g.a) / 2 * std::sqrt((P - z.birth_load) / (from.P - z.birth_load));
      z.geometry = ZoneGeometry(centre - w, centre + w);
    }
    const std::vector<double> ends = all_ends(guess);
    if (!std::is_sorted(ends.begin(), ends.end()) || std::adjacent_find(ends.begin(), ends.end()) != ends.end()) {
      guess = from.c;
    }
  }
  const ContactSolution last(surface_, from.c);
  double target = P;
  int retargets = 0;
  for (int approach = 0; approach < 12; ++approach) {
    std::optional<State> state = settle(guess, target);
    if (!state) return std::nullopt;
    Verification v = verify(ContactSolution(surface_, state->c), gap_tolerance * height_range_, pressure_tolerance);
    if (tracing()) {
      std::fprintf(stderr, "wavecontact trace: verified: lowest pressure %.3g at %.6g, lowest gap %.3g at %.6g, %zu penetration%s\n",
                   v.lowest_pressure, v.x_of_lowest_pressure, v.lowest_gap, v.x_of_lowest_gap, v.penetrations.size(),
                   v.penetrations.size() == 1 ? "" : "s");
    }
    if (!v.pressure_ok) return std::nullopt;
    if (v.penetrations.empty()) return state;
    // The earliest event: where the gap at a penetration's deepest point reaches 0, by the
    // secant between the last admissible load and this one. Once (twice at most), aim where
    // the deepest new zone would start about birth_width wide (a zone of half-width w at a
    // depth 2 kappa w^2 below its gap's curvature kappa; the depth grows linearly with the
    // load) when that is well before the target.
    double event = target, aim = target;
    const double width = birth_width * surface_->resolution;
    for (const Penetration& p : v.penetrations) {
      const double g0 = last.gap(p.x);
      if (!(g0 > 0)) continue;
      const double e = from.P + (target - from.P) * g0 / (g0 - p.depth);
      const double birth_depth = 2 * std::max(p.curvature, 0.0) * width * width;
      const double a = e + (target - e) * std::clamp(birth_depth / -p.depth, 0.02, 1.0);
      if (e < event) event = e;
      aim = std::min(aim, a);
    }
    if (retargets < 2 && event > from.P && aim < target && target - event > 0.05 * (target - from.P)) {
      target = aim, ++retargets;
      continue;
    }
    // New zones at every penetration, at most birth_width wide and clear of the others.
    Configuration c = state->c;
    for (const Penetration& p : v.penetrations) {
      const double g0 = last.gap(p.x);
      const double born = g0 > 0 ? from.P + (target - from.P) * g0 / (g0 - p.depth) : -1;
      // At the top or the valley (x^ = 0, pi) the zone runs through it.
      const double w0 = p.curvature > 0 ? 0.5 * std::sqrt(2 * -p.depth / p.curvature) : width;
      const double room = p.x == 0 ? p.hi - p.x : p.x == pi ? p.x - p.lo : std::min(p.x - p.lo, p.hi - p.x);
      const double w = std::min({w0, width, 0.25 * room});
      if (!(w > 0)) continue;
      ZoneUnknowns z = p.x - w <= 0 ? zone_of(0, p.x + w, continuation_nodes)
                                    : p.x + w >= pi ? zone_of(p.x - w, pi, continuation_nodes)
                                                    : zone_of(p.x - w, p.x + w, continuation_nodes);
      z.birth_load = born;
      const auto at = std::lower_bound(c.zones.begin(), c.zones.end(), z.geometry.a,
                                       [](const ZoneUnknowns& u, double a) { return u.geometry.a < a; });
      c.zones.insert(at, std::move(z));
    }
    const ZoneSystem system(*surface_, {true, target});
    system.relax(c);
    guess = std::move(c);
    (void)before;
  }
  return std::nullopt;
}

namespace {

// How far two solutions of one topology differ: the ends (to the period) and, on each zone,
// the pressure at 3 N + 8 points spread like Chebyshev's (to the largest pressure), short of
// a hundredth of the zone from a free end (there the pressure goes like the root of the
// distance to the end, whose own difference is the first term).
std::vector<double> zone_differences(const ContactSolution& a, const ContactSolution& b, double highest) {
  std::vector<double> difference;
  for (std::size_t k = 0; k < a.zone_count(); ++k) {
    const ZoneGeometry& g = a.zone(k);
    double worst = std::max(std::fabs(g.a - b.zone(k).a), std::fabs(g.b - b.zone(k).b)) / pi;
    const double margin = 0.01 * (g.b - g.a);
    const double lo = g.top() ? g.a : g.a + margin, hi = g.valley() ? g.b : g.b - margin;
    const int count = 3 * static_cast<int>(a.configuration().zones[k].d.size()) + 8;
    for (int i = 0; i <= count; ++i) {
      const double x = (lo + hi) / 2 - (hi - lo) / 2 * std::cos(pi * i / count);
      worst = std::max(worst, std::fabs(a.pressure(x) - b.pressure(x)) / highest);
    }
    difference.push_back(worst);
  }
  return difference;
}

}  // namespace

SolvedContact ContactSolver::polish(const State& state) const {
  // The nodes of each zone double until its pressure and ends change by less than a tenth of
  // the tolerance (or, fixed, are compared with half as many again); the error estimate is the
  // last change, that of the coarser solution: an upper bound while the series converge.
  const ZoneSystem system(*surface_, {true, state.P});
  const auto solve = [&](Configuration start) {
    system.relax(start);
    const ZoneSystem::Result r = system.newton(start, final_residual, [&] { check_budget(); });
    if (r.outcome != ZoneSystem::Outcome::converged && !(r.residual < 1e-9)) {
      throw BeyondReach("wavecontact::solve_contact: Newton's method did not converge polishing the contact at P = " +
                        std::to_string(state.P));
    }
    return r.configuration;
  };
  Configuration c = state.c;
  if (fixed_nodes_ > 0) {
    for (ZoneUnknowns& z : c.zones) z.d.resize(static_cast<std::size_t>(fixed_nodes_), 0.0);
  }
  c = solve(c);
  // A zone keeps doubling while its change is above a tenth of the tolerance and still falls
  // (by four at least: below, its rounding is reached).
  std::vector<double> difference, previous(c.zones.size(), std::numeric_limits<double>::infinity());
  std::vector<bool> converging(c.zones.size(), true);
  double highest = verify(ContactSolution(surface_, c), gap_tolerance * height_range_, pressure_tolerance).highest_pressure;
  for (int round = 0; round < 10; ++round) {
    Configuration finer = c;
    bool grown = false;
    for (std::size_t k = 0; k < finer.zones.size(); ++k) {
      const bool again = difference.empty() || (difference[k] > 0.1 * tolerance_ && converging[k]);
      const std::size_t n = finer.zones[k].d.size();
      const std::size_t target = fixed_nodes_ > 0 ? n + n / 2 : std::min<std::size_t>(most_nodes, 2 * n);
      if (again && target > n) finer.zones[k].d.resize(target, 0.0), grown = true;
    }
    if (!grown) break;
    finer = solve(finer);
    const std::vector<double> change = zone_differences(ContactSolution(surface_, c), ContactSolution(surface_, finer), highest);
    for (std::size_t k = 0; k < change.size(); ++k) {
      if (finer.zones[k].d.size() != c.zones[k].d.size()) {
        converging[k] = change[k] < 0.25 * previous[k];
        previous[k] = change[k];
      }
    }
    difference = change;
    if (fixed_nodes_ > 0) break;
    c = std::move(finer);
  }
  auto solution = std::make_shared<const ContactSolution>(surface_, c);
  const Verification v = verify(*solution, gap_tolerance * height_range_, pressure_tolerance);
  const double error = difference.empty() ? 0.0 : *std::max_element(difference.begin(), difference.end());
  int nodes = 0;
  for (const ZoneUnknowns& z : c.zones) nodes = std::max(nodes, static_cast<int>(z.d.size()));
  // Rounding: each zone's load comes from the T_0 coefficient of a sum whose terms reach
  // |C| + (E/2)|y| + sum |Psi_l|.
  double rounding = 0, largest = 0;
  for (const ZoneUnknowns& z : c.zones) {
    double magnitude = 0;
    for (double d : z.d) magnitude += std::fabs(d);
    largest = std::max(largest, magnitude);
  }
  for (std::size_t k = 0; k < c.zones.size(); ++k) {
    const ZoneGeometry& g = c.zones[k].geometry;
    const double x = (g.a + g.b) / 2;
    double terms = std::fabs(c.C) + surface_->E / 2 * std::fabs(surface_->depth(x));
    for (std::size_t l = 0; l < c.zones.size(); ++l) {
      if (l == k) continue;
      const ZoneUnknowns& z = c.zones[l];
      terms += std::fabs(far_potential(z.geometry, z.d.data(), static_cast<int>(z.d.size()), x));
    }
    rounding = std::max(rounding, std::numeric_limits<double>::epsilon() * terms / (g.h * self_logarithm(g)) / largest);
  }
  // Admissible within the error of the solution itself (a gap of the estimate's order next to
  // an end whose place is as uncertain).
  const double allowed = std::max(gap_tolerance, 10 * std::max(error, rounding)) * height_range_;
  if (!v.pressure_ok || v.lowest_gap < -allowed) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "wavecontact::solve_contact: the polished contact at P = %.6g is not admissible (lowest pressure "
                  "%.3g, lowest gap %.3g)",
                  state.P, v.lowest_pressure, v.lowest_gap);
    throw BeyondReach(text);
  }
  return {solution, state.P, std::max(error, rounding), rounding, nodes};
}

std::vector<SolvedContact> ContactSolver::solve(const std::vector<double>& loads) const {
  std::vector<std::size_t> order(loads.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return loads[a] < loads[b]; });
  std::vector<SolvedContact> solved(loads.size());
  std::optional<State> state, before;
  for (std::size_t index : order) {
    const double target = loads[index];
    target_load_ = target;
    if (target >= onset_) {
      solved[index] = full_contact(target);
      continue;
    }
    if (!state) {
      if (std::optional<State> direct = single_zone(target)) {
        solved[index] = polish(*direct);
        continue;
      }
      state = seed(target);
    }
    double ratio = 1;
    while (state->P < target) {
      reached_load_ = state->P, reached_zones_ = state->c.zones.size();
      check_budget();
      // A zone born at P_b widens like sqrt(P - P_b): a step that would more than double
      // its width is shortened.
      double next = std::min(target, state->P * (1 + ratio));
      for (const ZoneUnknowns& z : state->c.zones) {
        if (z.birth_load >= 0 && state->P > z.birth_load) next = std::min(next, z.birth_load + 4 * (state->P - z.birth_load));
      }
      std::optional<State> reached = advance(*state, before ? &*before : nullptr, next);
      if (!reached) {
        ratio /= 4;
        if (ratio < smallest_step) {
          throw BeyondReach("wavecontact::solve_contact: the continuation stalled at P = " + std::to_string(state->P) +
                            " (" + std::to_string(state->c.zones.size()) + " zones in half a period) on the way to " +
                            std::to_string(target));
        }
        continue;
      }
      if (same_topology(reached->c, state->c)) {
        before = std::move(state);
      } else {
        before.reset();
      }
      const bool full_step = reached->P >= next;
      state = std::move(reached);
      if (full_step) ratio = std::min(4.0, ratio * 2);
    }
    reached_load_ = state->P, reached_zones_ = state->c.zones.size();
    solved[index] = polish(*state);
  }
  return solved;
}

SingleZoneResult check_single_zone(const std::shared_ptr<const SurfaceModel>& surface, double a) {
  // One zone [0, a^] alone: its coefficients d_j = j G_j / h (j >= 1) from the transform of
  // (E/2) y, d_0 from the condition at a^ (bounded), C from the T_0 row; the nodes grow until
  // the tail is negligible.
  const ZoneGeometry g(0, a);
  const double half_E = surface->E / 2;
  int count = continuation_nodes;
  Configuration c;
  for (;;) {
    const std::vector<double> x = g.angles_of(chebyshev::nodes(count));
    const double x_ref = x[static_cast<std::size_t>(count / 2)];
    const std::shared_ptr<const KinkCorrection> kink = KinkCorrection::of(*surface, g);
    std::vector<double> values, G(static_cast<std::size_t>(count));
    for (double xi : x) {
      values.push_back(half_E * surface->height_difference(xi, x_ref) - (kink ? kink->potential(xi) : 0.0));
    }
    chebyshev::coefficients(values.data(), count, G.data());
    G[0] += half_E * surface->depth(x_ref);
    ZoneUnknowns z{g, std::vector<double>(static_cast<std::size_t>(count))};
    double alternating = 0, magnitude = 0;
    for (int j = 1; j < count; ++j) {
      z.d[static_cast<std::size_t>(j)] = j * G[static_cast<std::size_t>(j)] / g.h;
      alternating += (j % 2 == 0 ? 1 : -1) * z.d[static_cast<std::size_t>(j)];
      magnitude += std::fabs(z.d[static_cast<std::size_t>(j)]);
    }
    z.d[0] = -alternating;  // sum_j (-1)^j d_j = 0 at tau = -1 (x^ = a)
    c.C = g.h * self_logarithm(g) * z.d[0] - G[0];
    const double tail = std::fabs(z.d[static_cast<std::size_t>(count - 1)]) + std::fabs(z.d[static_cast<std::size_t>(count - 2)]);
    c.zones = {std::move(z)};
    if (tail <= 1e-15 * magnitude || count >= most_nodes) break;
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
