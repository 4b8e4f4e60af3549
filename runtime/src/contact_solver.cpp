#include "contact_solver.hpp"


#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>
#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/minima.hpp>

namespace wavecontact::detail {

namespace {

constexpr double pi = boost::math::double_constants::pi;
constexpr double two_pi = boost::math::double_constants::two_pi;
// While continuing, the quadrature and Newton's method need only find the zones (order 6
// places the ends within 1e-8 to 1e-11); the final orders polish them (first_order, then
// order_step more until the estimate meets the tolerance).
constexpr int continuation_order = 6;
constexpr double continuation_residual = 1e-10;
constexpr int first_order = 12, order_step = 4, last_order = 40;
constexpr int newton_iterations = 30;
constexpr double residual_tolerance = 1e-14;  // residuals are relative to their terms
constexpr double stagnation_floor = 1e-9;      // below it, a stalled Newton step is rounding
constexpr double pressure_tolerance = 1e-9;   // p >= -this * max p on the zones
constexpr double penetration_tolerance = 1e-9;  // gap >= -this * (max y - min y) off them
constexpr double confirmed_depth = 1e-6;  // of max y - min y: shallower, checked at order 12
constexpr int topology_changes = 16;
constexpr int max_zones = 64;  // in half a period
constexpr double merge_ratio = 1e-2;  // a gap this much narrower than its zones may merge
constexpr double merge_ahead_ratio = 0.1;  // a closing gap this narrow may merge ahead
constexpr double narrow_stretch = 0.1;  // of its neighbours: differenced by its width
constexpr double rounding_limit = 1e-8;  // of the pressure: beyond it the zones cannot be resolved
// A new zone starts about this wide (x^) relative to the surface's resolution.
constexpr double birth_width = 1.0 / 64;
constexpr double smallest_step = 1e-9;
constexpr double onset_margin = 1e-4;  // far above the onset's error at the continuation order (1e-7)

// Every end of the zones in increasing x^, with 0 and pi around them.
std::vector<double> all_ends(const std::vector<Zone>& zones) {
  std::vector<double> ends{0};
  for (const Zone& z : zones) ends.push_back(z.lo), ends.push_back(z.hi);
  ends.push_back(pi);
  return ends;
}

bool same_topology(const std::vector<Zone>& a, const std::vector<Zone>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if ((a[k].lo == 0) != (b[k].lo == 0) || (a[k].hi == pi) != (b[k].hi == pi)) return false;
  }
  return true;
}

// The zones with the penetrated regions added (overlapping ones merged).
std::vector<Zone> with_zones(std::vector<Zone> zones, const std::vector<Zone>& added) {
  zones.insert(zones.end(), added.begin(), added.end());
  std::sort(zones.begin(), zones.end(), [](const Zone& a, const Zone& b) { return a.lo < b.lo; });
  std::vector<Zone> merged;
  for (const Zone& z : zones) {
    if (!merged.empty() && z.lo <= merged.back().hi) {
      merged.back().hi = std::max(merged.back().hi, z.hi);
    } else {
      merged.push_back(z);
    }
  }
  return merged;
}

// Zones k and k + 1 as one (the gap between them closed).
void merge_with_next(std::vector<Zone>& zones, std::size_t k) {
  zones[k].hi = zones[k + 1].hi;
  zones.erase(zones.begin() + static_cast<std::ptrdiff_t>(k) + 1);
}

// The largest pressure at the samples of a prepared inversion (0 if none is positive).
double highest_pressure(const IntervalInversion& inversion) {
  double highest = 0;
  for (const auto& s : inversion.pressure_samples()) highest = std::max(highest, s.value);
  return highest;
}

// The highest point (x^) and the height range of the surface: a scan refined by Brent's method.
struct HeightScan {
  double top_angle, range;
};

HeightScan scan_height(const SurfaceSlope& surface) {
  const int samples = std::max(512, static_cast<int>(16 * pi / surface.resolution));
  auto height = [&](double x) { return surface.height(std::cos(x)); };
  double highest = -std::numeric_limits<double>::infinity(), lowest = -highest;
  int best = 0;
  for (int i = 0; i <= samples; ++i) {
    const double y = height(pi * i / samples);
    if (y > highest) highest = y, best = i;
    lowest = std::min(lowest, y);
  }
  HeightScan scan{pi * best / samples, 0};
  if (best > 0 && best < samples) {
    const auto [x, y] = boost::math::tools::brent_find_minima(
        [&](double x) { return -height(x); }, pi * (best - 1) / samples, pi * (best + 1) / samples, 52);
    scan.top_angle = x;
    highest = std::max(highest, -y);
  }
  scan.range = highest - lowest;
  return scan;
}

// The load (normalised) from which the contact is full, at a quadrature order. In full
// contact p = C - S with C fixed by the load, so p = P/(2 pi) + p0 and the onset is -2 pi min p0.
double full_contact_onset(const SurfaceSlope& surface, int order) {
  IntervalInversion full(surface, {{0, pi}}, order, IntervalInversion::Grading::evaluation);
  full.prepare(0);
  double p0 = std::numeric_limits<double>::infinity(), x0 = 0;
  for (const auto& s : full.pressure_samples()) {
    if (s.value < p0) p0 = s.value, x0 = s.x;
  }
  const double h = surface.resolution / 4;
  const double p_min = boost::math::tools::brent_find_minima(
      [&](double x) { return full.pressure(x); }, std::max(0.0, x0 - h), std::min(pi, x0 + h), 52).second;
  return std::max(0.0, -two_pi * std::min(p0, p_min));
}

// The local minima of f (x^ in [0, pi]) from its samples that may reach below `level`: every
// sample lower than its neighbours (or an end sample lower than its one neighbour), refined by
// Brent's method between them unless even a dip as deep again as its neighbours rise stays
// above the level. A dip narrower than the samples' spacing shows as its nearest sample.
template <typename F>
std::vector<IntervalInversion::Sample> local_minima(std::vector<IntervalInversion::Sample> samples, const F& f,
                                                    double level) {
  std::sort(samples.begin(), samples.end(),
            [](const auto& a, const auto& b) { return a.x < b.x || (a.x == b.x && a.value < b.value); });
  // Panels share their end points, whose two samples may differ in the last bit: the lower.
  samples.erase(std::unique(samples.begin(), samples.end(), [](const auto& a, const auto& b) { return a.x == b.x; }),
                samples.end());
  std::vector<IntervalInversion::Sample> minima;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const bool below_left = i == 0 || samples[i].value <= samples[i - 1].value;
    const bool below_right = i + 1 == samples.size() || samples[i].value < samples[i + 1].value;
    if (!below_left || !below_right) continue;
    const double a = i > 0 ? samples[i - 1].x : samples[i].x;
    const double b = i + 1 < samples.size() ? samples[i + 1].x : samples[i].x;
    const double rise = std::max(i > 0 ? samples[i - 1].value : samples[i].value,
                                 i + 1 < samples.size() ? samples[i + 1].value : samples[i].value) - samples[i].value;
    IntervalInversion::Sample best = samples[i];
    if (samples[i].value - rise > level) continue;
    if (b > a) {
      const auto [x, value] = boost::math::tools::brent_find_minima(f, a, b, 40);
      if (value < best.value) best = {x, value};
    }
    minima.push_back(best);
  }
  return minima;
}

}  // namespace

ContactSolver::ContactSolver(SurfaceSlope surface, double tolerance, int order, WorkBudget budget)
    : surface_(std::move(surface)), tolerance_(tolerance), budget_(std::move(budget)), fixed_order_(order) {
  const HeightScan scan = scan_height(surface_);
  top_angle_ = scan.top_angle;
  height_range_ = scan.range;
  onset_estimate_ = full_contact_onset(surface_, continuation_order);
}

void ContactSolver::check_budget() const {
  budget_.check([&] {
    char loads[96];
    std::snprintf(loads, sizeof loads, "the continuation reached P = %.6g of %.6g, ", reached_load_, target_load_);
    return loads + std::to_string(reached_zones_) +
           (reached_zones_ == 1 ? " zone" : " zones") + " in half a period";
  });
}

double ContactSolver::full_contact_load() const {
  if (!onset_) onset_ = full_contact_onset(surface_, first_order);
  return *onset_;
}

ContactSolver::NewtonResult ContactSolver::newton(std::vector<Zone> zones, double P, int order,
                                                  double tolerance, Eigen::MatrixXd& J) const {
  // One panel layout for the iterates, so that the discrete conditions are smooth in the
  // ends; laid out afresh when a stretch (zone or gap) has changed by half or more, since its
  // panels are graded for the stretches it was made for.
  const IntervalInversion start(surface_, zones, order);
  std::shared_ptr<IntervalInversion::Layout> layout = start.layout();
  std::vector<double> x = start.free_ends();
  const auto n = static_cast<Eigen::Index>(x.size());
  if (n == 0) return {Outcome::converged, zones};
  auto stretches = [&](const std::vector<double>& ends) {
    const std::vector<double> e = all_ends(IntervalInversion::with_free_ends(zones, ends));
    std::vector<double> lengths;
    for (std::size_t i = 0; i + 1 < e.size(); ++i) lengths.push_back(e[i + 1] - e[i]);
    return lengths;
  };
  std::vector<double> laid_out = stretches(x);
  auto residual = [&](const std::vector<double>& ends) {
    const std::vector<double> r = IntervalInversion(surface_, IntervalInversion::with_free_ends(zones, ends), order,
                                                    IntervalInversion::Grading::quadrature, layout)
                                      .residuals(P);
    return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(r.data(), n));
  };
  // The Jacobian by forward differences, each end moved by a small part of the shorter
  // stretch (zone or gap) next to it. A stretch between two free ends narrower than a tenth
  // of its neighbours (a zone just opened, a gap about to close) is moved as a whole and
  // widened, each by its own difference: the conditions depend on its width w only to order
  // w^2, so its ends' columns nearly cancel, and their difference taken apart is rounding.
  auto differences = [&](const std::vector<double>& at, const Eigen::VectorXd& r_at) {
    const std::vector<double> ends = all_ends(IntervalInversion::with_free_ends(zones, at));
    auto length = [&](std::size_t e) { return ends[e + 1] - ends[e]; };  // of ends[e] .. ends[e + 1]
    auto column = [&](Eigen::Index a, double move_a, Eigen::Index b, double move_b, double h) {
      std::vector<double> moved = at;
      moved[static_cast<std::size_t>(a)] += move_a * h;
      moved[static_cast<std::size_t>(b)] += move_b * h;
      return Eigen::VectorXd((residual(moved) - r_at) / h);
    };
    Eigen::MatrixXd D(n, n);
    Eigen::Index j = 0;
    for (std::size_t e = 1; e + 1 < ends.size(); ++e) {
      if (ends[e] == 0 || ends[e] == pi) continue;
      const bool narrow = e + 2 < ends.size() && ends[e + 1] != pi &&
                          length(e) < narrow_stretch * std::min(length(e - 1), length(e + 1));
      if (!narrow) {
        const double h = 1e-7 * std::min(length(e - 1), length(e));
        D.col(j) = column(j, 1, j, 0, h);
        ++j;
        continue;
      }
      // Ends a = j and b = j + 1 moved by da = s - w/2, db = s + w/2: the columns are
      // J_s/2 - J_w and J_s/2 + J_w.
      const Eigen::VectorXd shift = column(j, 1, j + 1, 1, 1e-7 * std::min(length(e - 1), length(e + 1)));
      const Eigen::VectorXd widen = column(j, -0.5, j + 1, 0.5, 1e-3 * length(e));
      D.col(j) = shift / 2 - widen;
      D.col(j + 1) = shift / 2 + widen;
      j += 2, ++e;
    }
    return D;
  };
  Eigen::VectorXd r = residual(x);
  bool fresh = J.rows() != n || J.cols() != n;
  std::size_t closing = static_cast<std::size_t>(-1);  // the stretch the last step overshot
  if (fresh) J = differences(x, r);
  for (int iteration = 0; iteration < newton_iterations; ++iteration) {
    check_budget();
    const std::vector<Zone> current = IntervalInversion::with_free_ends(zones, x);
    const std::vector<double> now = stretches(x);
    for (std::size_t i = 0; i < now.size(); ++i) {
      if (laid_out[i] > 0 && (now[i] > 1.5 * laid_out[i] || now[i] < laid_out[i] / 1.5)) {
        layout = std::make_shared<IntervalInversion::Layout>();
        laid_out = now;
        r = residual(x);
        J = differences(x, r), fresh = true;
        break;
      }
    }
    if (r.lpNorm<Eigen::Infinity>() < tolerance) return {Outcome::converged, current};
    const Eigen::VectorXd delta = J.fullPivLu().solve(-r);
    if (!delta.allFinite()) return {Outcome::failed, current};
    // Damped so that every stretch keeps a tenth of its length; a stretch that would close
    // is an event: a gap between zones (merge), or the stretch to the top or the valley.
    const std::vector<double> ends = all_ends(current);
    std::vector<double> change(ends.size(), 0.0);
    for (std::size_t e = 1, j = 0; e + 1 < ends.size(); ++e) {
      if (ends[e] != 0 && ends[e] != pi) change[e] = delta[static_cast<Eigen::Index>(j++)];
    }
    double lambda = 1;
    std::size_t limiting = 0;
    for (std::size_t e = 0; e + 1 < ends.size(); ++e) {
      const double length = ends[e + 1] - ends[e], shrink = change[e] - change[e + 1];
      if (length > 0 && shrink > 0 && lambda * shrink > 0.9 * length) {
        lambda = 0.9 * length / shrink;
        limiting = e;
      }
    }
    // A full step that would close ends[limiting] .. ends[limiting + 1] twice running (the
    // first steps from a new zone are not to be trusted that far), or a stretch already
    // next to nothing, is an event: 0..lo of the first zone (top), hi..pi of the last
    // (valley), or hi of zone k .. lo of zone k + 1 (merge).
    const bool overshoots = lambda < 1 && change[limiting] - change[limiting + 1] >= ends[limiting + 1] - ends[limiting];
    const bool again = overshoots && closing == limiting;
    closing = overshoots ? limiting : ends.size();
    const double remaining = (ends[limiting + 1] - ends[limiting]) - lambda * (change[limiting] - change[limiting + 1]);
    if (again || (lambda < 1 && remaining < 1e-6 * pi)) {
      if (limiting == 0) return {Outcome::top, current};
      if (limiting == ends.size() - 2) return {Outcome::valley, current};
      if (limiting % 2 == 0) return {Outcome::merge, current, limiting / 2 - 1};
      return {Outcome::failed, current};  // a zone would vanish
    }
    // Backtracking along the step while the residuals grow (with a fresh Jacobian only).
    std::vector<double> next;
    Eigen::VectorXd r_next;
    for (int halving = 0;; ++halving, lambda /= 2) {
      next = x;
      for (Eigen::Index i = 0; i < n; ++i) next[static_cast<std::size_t>(i)] += lambda * delta[i];
      r_next = residual(next);
      if (!fresh || halving == 6 || r_next.lpNorm<Eigen::Infinity>() < r.lpNorm<Eigen::Infinity>()) break;
    }
    if (r_next.lpNorm<Eigen::Infinity>() < r.lpNorm<Eigen::Infinity>()) {
      // Broyden's update of the Jacobian along the step.
      Eigen::VectorXd s(n);
      for (Eigen::Index i = 0; i < n; ++i) s[i] = next[static_cast<std::size_t>(i)] - x[static_cast<std::size_t>(i)];
      J += ((r_next - r) - J * s) * s.transpose() / s.squaredNorm();
      const bool stalled = s.lpNorm<Eigen::Infinity>() < 1e-14 * pi && r_next.lpNorm<Eigen::Infinity>() < 1e-9;
      x = std::move(next), r = r_next, fresh = false;
      if (stalled) return {Outcome::converged, IntervalInversion::with_free_ends(zones, x)};
    } else if (!fresh) {
      J = differences(x, r), fresh = true;  // the Jacobian was stale
    } else if (r.lpNorm<Eigen::Infinity>() < stagnation_floor) {
      return {Outcome::converged, current};  // rounding: no step decreases the residuals
    } else {
      return {Outcome::failed, current};
    }
  }
  return {Outcome::failed, zones};
}

std::optional<ContactSolver::State> ContactSolver::settle(std::vector<Zone> zones, double P,
                                                          Eigen::MatrixXd jacobian) const {
  for (int change = 0; change < topology_changes; ++change) {
    const NewtonResult result = newton(zones, P, continuation_order, continuation_residual, jacobian);
    zones = result.zones;
    switch (result.outcome) {
      case Outcome::converged: {
        auto inversion = std::make_shared<IntervalInversion>(surface_, zones, continuation_order,
                                                             IntervalInversion::Grading::evaluation);
        inversion->prepare(P);
        return State{zones, P, std::move(jacobian), std::move(inversion)};
      }
      case Outcome::merge:
        merge_with_next(zones, result.index);
        break;
      case Outcome::top:
        zones.front().lo = 0;
        break;
      case Outcome::valley:
        zones.back().hi = pi;
        break;
      case Outcome::failed: {
        // Next to a gap much narrower than its zones, Newton may fail before the merge shows:
        // merge the narrowest such gap (the pressure check then judges it).
        std::size_t narrowest = zones.size();
        double ratio = merge_ratio;
        for (std::size_t k = 0; k + 1 < zones.size(); ++k) {
          const double gap = zones[k + 1].lo - zones[k].hi;
          const double zone = std::min(zones[k].hi - zones[k].lo, zones[k + 1].hi - zones[k + 1].lo);
          if (gap < ratio * zone) ratio = gap / zone, narrowest = k;
        }
        if (narrowest == zones.size()) return std::nullopt;
        merge_with_next(zones, narrowest);
        break;
      }
    }
    jacobian.resize(0, 0);
  }
  return std::nullopt;
}

ContactSolver::Check ContactSolver::check(const IntervalInversion& inversion) const {
  if (inversion.rounding() > rounding_limit) {
    char rounding[32];
    std::snprintf(rounding, sizeof rounding, "%.2g", inversion.rounding());
    throw BeyondReach(
        "wavecontact::solve_contact: the contact reaches " + std::to_string(inversion.zones().size()) +
        (inversion.zones().size() == 1 ? " zone" : " zones") +
        " in half a period, clustered so that rounding alone reaches " + rounding +
        " of the pressure (the several-interval formula multiplies the distances between all zone ends): "
        "beyond the solver's range; a smaller load or fewer, larger asperities are within it");
  }
  Check result{true, {}};
  const double highest = highest_pressure(inversion);
  const auto pressure = [&](double x) { return inversion.pressure(x); };
  for (const IntervalInversion::Sample& m : local_minima(inversion.pressure_samples(), pressure, 0.0)) {
    result.pressure_ok = result.pressure_ok && !(m.value < -pressure_tolerance * highest);
  }
  const double floor = -penetration_tolerance * height_range_;
  const auto gap = [&](double x) { return inversion.gap(x); };
  // Next to a zone end, where the gap rises like the 3/2 power of the distance, the
  // continuation's order errs in it by up to about 2e-8 of the height range: a shallow
  // penetration holds only if the same zones at the polishing order confirm it.
  std::optional<IntervalInversion> polished;
  for (const IntervalInversion::Sample& m : local_minima(inversion.gap_samples(), gap, 0.0)) {
    if (!(m.value < floor)) continue;
    if (m.value > -confirmed_depth * height_range_) {
      if (!polished) {
        polished.emplace(surface_, inversion.zones(), first_order, IntervalInversion::Grading::evaluation);
        polished->prepare(2 * polished->half_load());
      }
      if (!(polished->gap(m.x) < floor)) continue;
    }
    // The gap near its lowest point is a parabola; the zone starts at 0.7 of the stretch
    // where it is negative (a Hertzian zone is narrower than the overlap).
    const double h = std::min(surface_.resolution, pi) * 1e-3;
    const double left = gap(std::max(0.0, m.x - h)), right = gap(std::min(pi, m.x + h));
    const double curvature = ((m.x - h < 0 ? right : left) - 2 * m.value + (m.x + h > pi ? left : right)) / (h * h);
    const double half = curvature > 0 ? 0.7 * std::sqrt(2 * -m.value / curvature) : h;
    const double lo = m.x - half <= 0 ? 0 : m.x - half, hi = m.x + half >= pi ? pi : m.x + half;
    result.penetrations.push_back({{lo, hi}, m.x, m.value, std::max(curvature, 0.0)});
  }
  return result;
}

std::optional<ContactSolver::State> ContactSolver::single_zone(double P) const {
  if (top_angle_ != 0) return std::nullopt;
  // From a small zone, scaled as in Hertz's contact (a^2 ~ P).
  const double a0 = std::min(0.05, surface_.resolution / 8);
  const double P0 = 2 * IntervalInversion(surface_, {{0, a0}}, continuation_order).half_load();
  if (!(P0 > 0)) return std::nullopt;
  std::optional<State> state = settle({{0, std::min(0.9 * pi, a0 * std::sqrt(P / P0))}}, P, {});
  if (!state) return std::nullopt;
  const Check c = check(*state->inversion);
  if (!c.pressure_ok || !c.penetrations.empty()) return std::nullopt;
  return state;
}

ContactSolver::State ContactSolver::seed(double P) const {
  // A small zone at the highest point carrying at most P.
  double width = std::min(0.05, surface_.resolution / 8);
  for (int attempt = 0; attempt < 200; ++attempt, width /= 4) {
    std::vector<Zone> zones;
    if (top_angle_ < width) {
      zones = {{0, width}};
    } else if (top_angle_ > pi - width) {
      zones = {{pi - width, pi}};
    } else {
      // Centred so that the pressure is bounded at both ends: Newton on the centre alone.
      double centre = top_angle_;
      for (int i = 0; i < 30; ++i) {
        auto r = [&](double c) {
          return IntervalInversion(surface_, {{c - width, c + width}}, continuation_order).residuals(1)[0];
        };
        const double h = 1e-7 * width, r0 = r(centre), slope = (r(centre + h) - r0) / h;
        const double step = std::clamp(-r0 / slope, -width / 2, width / 2);
        centre = std::clamp(centre + step, width * 1.01, pi - width * 1.01);
        if (std::fabs(step) < 1e-14 * width) break;
      }
      zones = {{centre - width, centre + width}};
    }
    const double load = 2 * IntervalInversion(surface_, zones, continuation_order).half_load();
    if (load > 0 && load <= P) {
      auto inversion = std::make_shared<IntervalInversion>(surface_, zones, continuation_order,
                                                           IntervalInversion::Grading::evaluation);
      inversion->prepare(load);
      return {zones, load, {}, std::move(inversion)};
    }
  }
  throw BeyondReach("wavecontact::solve_contact: no small contact zone carries the load " + std::to_string(P));
}

std::optional<ContactSolver::State> ContactSolver::advance(const State& from, double P,
                                                           const State* before) const {
  std::vector<Zone> guess = from.zones;
  if (before && same_topology(before->zones, from.zones) && from.P != before->P) {
    // Secant predictor for the free ends.
    const double t = (P - from.P) / (from.P - before->P);
    std::vector<double> a = IntervalInversion(surface_, before->zones, continuation_order).free_ends();
    std::vector<double> b = IntervalInversion(surface_, from.zones, continuation_order).free_ends();
    for (std::size_t i = 0; i < a.size(); ++i) b[i] += t * (b[i] - a[i]);
    const std::vector<double> ends = all_ends(IntervalInversion::with_free_ends(from.zones, b));
    if (std::is_sorted(ends.begin(), ends.end()) && std::adjacent_find(ends.begin(), ends.end()) == ends.end()) {
      guess = IntervalInversion::with_free_ends(from.zones, b);
    }
  }
  double target = P;
  for (int approach = 0; approach < 8; ++approach) {
    std::optional<State> state = settle(guess, target, from.jacobian);
    if (!state) return std::nullopt;
    Check c = check(*state->inversion);
    if (!c.pressure_ok) return std::nullopt;
    if (c.penetrations.empty()) return state;
    // The earliest event: where the gap at the deepest point of a penetration reaches 0,
    // by the secant between this load and the last admissible one. Well before the target,
    // aim just past it, where the new zone would be about birth_width wide (the depth
    // grows linearly with the load, the width like its root).
    double event = target, aim = target;
    for (const Penetration& p : c.penetrations) {
      const double g0 = from.inversion->gap(p.x);
      if (!(g0 > 0)) continue;
      const double e = from.P + (target - from.P) * g0 / (g0 - p.depth);
      if (e < event) {
        const double width = birth_width * surface_.resolution;
        const double birth_depth = 0.5 * p.curvature * width * width;
        event = e;
        aim = e + (target - e) * std::clamp(birth_depth / -p.depth, 0.02, 1.0);
      }
    }
    if (event > from.P && target - event > 0.05 * (target - from.P) && aim < target) {
      target = aim;
      continue;
    }
    // Just past the event: new zones start where the gap is negative, the deepest first
    // (a zone often shields its neighbours), one at a time.
    for (int opening = 0; opening < max_zones && !c.penetrations.empty(); ++opening) {
      const Penetration& deepest = *std::min_element(
          c.penetrations.begin(), c.penetrations.end(),
          [](const Penetration& u, const Penetration& v) { return u.depth < v.depth; });
      state = settle(with_zones(state->zones, {deepest.zone}), target, {});
      if (!state) return std::nullopt;
      c = check(*state->inversion);
      if (!c.pressure_ok) return std::nullopt;
    }
    if (c.penetrations.empty()) return state;
    return std::nullopt;
  }
  return std::nullopt;
}

// A gap of width w between two zones closes like the root of the load to go, w^2 ~ P_m - P:
// the ends move ever faster per load, their Jacobian turns singular, and the steps towards
// P_m shrink without reaching it. Beyond P_m the merged zones are the contact, with the
// lowest pressure of the merged zone (at the former gap) growing from 0 at P_m: P_m by the
// secant method on that pressure, from the estimate of w^2 linear in the load.
std::optional<ContactSolver::State> ContactSolver::merge_ahead(const State& from, const State& before,
                                                               double limit) const {
  if (!same_topology(before.zones, from.zones) || !(before.P < from.P)) return std::nullopt;
  std::size_t closing = from.zones.size();
  double merge_load = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k + 1 < from.zones.size(); ++k) {
    const double w = from.zones[k + 1].lo - from.zones[k].hi, w_before = before.zones[k + 1].lo - before.zones[k].hi;
    const double zone = std::min(from.zones[k].hi - from.zones[k].lo, from.zones[k + 1].hi - from.zones[k + 1].lo);
    if (!(w < w_before) || !(w < merge_ahead_ratio * zone)) continue;
    const double estimate = from.P + w * w * (from.P - before.P) / (w_before * w_before - w * w);
    if (estimate < merge_load) merge_load = estimate, closing = k;
  }
  if (closing == from.zones.size()) return std::nullopt;
  std::vector<Zone> merged = from.zones;
  merge_with_next(merged, closing);
  const Zone zone = merged[closing];
  // The lowest pressure on the merged zone, relative to the largest pressure.
  auto lowest = [&](const IntervalInversion& inversion) {
    double low = 0;
    const auto pressure = [&](double x) { return inversion.pressure(x); };
    for (const auto& m : local_minima(inversion.pressure_samples(), pressure, 0.0)) {
      if (m.x > zone.lo && m.x < zone.hi) low = std::min(low, m.value);
    }
    return low / highest_pressure(inversion);
  };
  double P_low = from.P, f_low = std::numeric_limits<double>::quiet_NaN();
  double P = std::min(limit, std::max(merge_load, from.P * (1 + 1e-6)));
  for (int iteration = 0; iteration < 12 && P > from.P && P <= limit; ++iteration) {
    std::optional<State> state = settle(merged, P, {});
    if (!state || state->zones.size() != merged.size()) return std::nullopt;
    const double f = lowest(*state->inversion);
    if (!(f < -pressure_tolerance)) {
      const Check c = check(*state->inversion);
      return c.pressure_ok && c.penetrations.empty() ? state : std::nullopt;
    }
    // Below P_m: the secant through the last two loads below it (the first from the
    // estimate's step), aiming a thousandth of the step beyond the root.
    const double next = std::isnan(f_low) ? P + 2 * (P - P_low) : P - f * (P - P_low) / (f - f_low);
    P_low = P, f_low = f;
    if (!(next > P)) return std::nullopt;
    P = std::min(limit, next + 1e-3 * (next - P));
    if (P == P_low) return std::nullopt;
  }
  return std::nullopt;
}

SolvedContact ContactSolver::refine(const State& state) const {
  std::vector<Zone> zones = state.zones;
  Eigen::MatrixXd jacobian = state.jacobian;
  auto solve_at = [&](int order) {
    const NewtonResult result = newton(zones, state.P, order, residual_tolerance, jacobian);
    if (result.outcome != Outcome::converged) {
      throw BeyondReach("wavecontact::solve_contact: Newton's method did not converge at order " +
                               std::to_string(order) + " for the load " + std::to_string(state.P));
    }
    zones = result.zones;
    auto prepared = std::make_shared<IntervalInversion>(surface_, zones, order, IntervalInversion::Grading::evaluation);
    prepared->prepare(state.P);
    return prepared;
  };
  // The estimate of a against b: ends (to the period) and pressure (to its largest), and
  // a's rounding error.
  auto estimate = [](const IntervalInversion& a, const IntervalInversion& b) {
    const std::vector<double> ea = a.free_ends(), eb = b.free_ends();
    double highest = 0, worst = 0;
    for (const auto& s : a.pressure_samples()) highest = std::max(highest, std::fabs(s.value));
    for (std::size_t i = 0; i < ea.size(); ++i) worst = std::max(worst, std::fabs(ea[i] - eb[i]) / pi);
    // Between a's samples (its interpolation points, where its tables are exact), inside
    // both solutions' zones.
    std::vector<IntervalInversion::Sample> samples = a.pressure_samples();
    std::sort(samples.begin(), samples.end(), [](const auto& u, const auto& v) { return u.x < v.x; });
    for (std::size_t i = 1; i < samples.size(); ++i) {
      const double x = (samples[i - 1].x + samples[i].x) / 2, p = a.pressure(x), q = b.pressure(x);
      if (p == 0 || q == 0) continue;
      worst = std::max(worst, std::fabs(q - p) / highest);
      if (i % 3 == 0) worst = std::max(worst, a.rounding_amplification(x) * std::fabs(p) / highest);
    }
    return worst;
  };
  if (fixed_order_ > 0) {  // against the next order, order + 2
    auto result = solve_at(fixed_order_);
    const std::vector<Zone> at_order = zones;
    const double error = estimate(*result, *solve_at(fixed_order_ + 2));
    return {at_order, state.P, fixed_order_, error, result};
  }
  // 12, 16, ... until the change from the previous order meets the tolerance; from the
  // continuation's order 6 when the tolerance allows (order 6 errs by 1e-11 to 2e-8).
  const int start = tolerance_ >= 1e-8 ? continuation_order : first_order;
  std::shared_ptr<const IntervalInversion> previous = solve_at(start);
  for (int order = start + order_step;; order += order_step) {
    auto current = solve_at(order);
    const double error = estimate(*current, *previous);
    if (error <= tolerance_ || order + order_step > last_order) return {zones, state.P, order, error, current};
    previous = std::move(current);
  }
}

std::vector<SolvedContact> ContactSolver::solve(const std::vector<double>& loads) const {
  std::vector<std::size_t> order(loads.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return loads[a] < loads[b]; });
  std::vector<SolvedContact> solved(loads.size());
  std::optional<State> state, before;
  std::optional<SolvedContact> full;  // full contact, p = P/(2 pi) + p0: one solution for every load
  for (std::size_t index : order) {
    const double target = loads[index];
    // The estimate decides unless the load is within its error of the onset.
    const bool full_contact = std::fabs(target - onset_estimate_) > onset_margin * onset_estimate_
                                  ? target > onset_estimate_
                                  : target >= full_contact_load();
    if (full_contact) {
      if (!full) {
        full = refine({{{0, pi}}, target, {}, nullptr});
      } else {
        auto shifted = std::make_shared<IntervalInversion>(*full->inversion);
        shifted->shift_full_contact_load(target);
        full->P = target, full->inversion = std::move(shifted);
      }
      solved[index] = *full;
      continue;
    }
    if (!state) {
      if (std::optional<State> direct = single_zone(target)) {
        solved[index] = refine(*direct);
        continue;
      }
      state = seed(target);
    }
    double ratio = 1;  // the next load is at most (1 + ratio) times the last
    target_load_ = target;
    while (state->P < target) {
      reached_load_ = state->P, reached_zones_ = state->zones.size();
      check_budget();
      const double next = std::min(target, state->P * (1 + ratio));
      std::optional<State> reached = advance(*state, next, before ? &*before : nullptr);
      if (!reached && before) reached = merge_ahead(*state, *before, target);
      if (!reached) {
        ratio /= 4;
        if (ratio < smallest_step) {
          throw BeyondReach("wavecontact::solve_contact: the continuation stalled at P = " +
                                   std::to_string(state->P) + " (" + std::to_string(state->zones.size()) +
                                   " zones in half a period) on the way to " + std::to_string(target) +
                                   ": events too close together for the solver");
        }
        continue;
      }
      if (same_topology(reached->zones, state->zones)) {
        before = std::move(state);
      } else {
        before.reset();
      }
      // A full step, or a merge ahead beyond it, lengthens the next.
      const double reached_ratio = reached->P / state->P - 1;
      const bool full_step = reached->P >= next;
      state = std::move(reached);
      if (full_step) ratio = std::clamp(std::max(ratio * 2, reached_ratio), ratio, 4.0);
    }
    solved[index] = refine(*state);
  }
  return solved;
}

SingleZoneResult check_single_zone(const SurfaceSlope& surface, double a) {
  IntervalInversion inversion(surface, {{0, a}}, first_order, IntervalInversion::Grading::evaluation);
  inversion.prepare(2 * inversion.half_load());
  SingleZoneResult result{true, false, 0, 0, 0, 0};
  const double highest = highest_pressure(inversion);
  const double anything = std::numeric_limits<double>::infinity();
  for (const auto& m : local_minima(inversion.pressure_samples(), [&](double x) { return inversion.pressure(x); }, anything)) {
    if (m.value < result.lowest_pressure) result.lowest_pressure = m.value, result.x_of_lowest_pressure = m.x;
  }
  for (const auto& m : local_minima(inversion.gap_samples(), [&](double x) { return inversion.gap(x); }, anything)) {
    if (m.value < result.lowest_gap) result.lowest_gap = m.value, result.x_of_lowest_gap = m.x;
  }
  result.penetrates = result.lowest_gap < -penetration_tolerance * scan_height(surface).range;
  result.solution = !(result.lowest_pressure < -pressure_tolerance * highest) && !result.penetrates;
  return result;
}

}  // namespace wavecontact::detail
