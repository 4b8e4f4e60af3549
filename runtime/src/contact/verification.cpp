#include "verification.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>

#include <boost/math/tools/minima.hpp>

#include "chebyshev.hpp"
#include "constants.hpp"
#include "support/parallel.hpp"

namespace wavecontact::detail {

namespace {

// Brent's method on [a, b] (either order) with f at one point.
std::pair<double, double> brent(const BatchFunction& f, double a, double b) {
  const auto one = [&](double x) {
    double value;
    f(&x, &value, 1);
    return value;
  };
  return boost::math::tools::brent_find_minima(one, std::min(a, b), std::max(a, b), 40);
}

// The lowest of f between the end sample `end` (value `at_end`) and its neighbour: the probes
// end + (neighbour - end) 2^-k, k = 1, 2, ..., end_probes at most and none closer to the end
// than `closest`, and where one lies below the end, Brent's method between the probes (or the
// neighbour, or the end) beside the lowest.
std::pair<double, double> towards_the_end(const BatchFunction& f, double end, double at_end, double neighbour,
                                          double closest) {
  std::array<double, end_probes + 2> x;  // x[0] the neighbour, x[1 .. count] the probes, then the end
  std::array<double, end_probes> probe;
  x[0] = neighbour;
  std::size_t count = 0;
  while (count < end_probes) {
    const double at = end + (neighbour - end) * std::ldexp(1.0, -static_cast<int>(count + 1));
    if (!(std::fabs(at - end) >= closest)) break;
    x[++count] = at;
  }
  if (count == 0) return {end, at_end};
  x[count + 1] = end;
  f(x.data() + 1, probe.data(), count);
  const auto lowest = std::min_element(probe.begin(), probe.begin() + static_cast<std::ptrdiff_t>(count));
  if (!(*lowest < at_end)) return {end, at_end};
  const std::size_t k = static_cast<std::size_t>(lowest - probe.begin()) + 1;
  std::pair<double, double> best{x[k], *lowest};
  const auto refined = brent(f, x[k - 1], x[k + 1]);
  if (refined.second < best.second) best = refined;
  return best;
}

}  // namespace

std::vector<std::pair<double, double>> local_minima(const std::vector<double>& xs, const std::vector<double>& values,
                                                    const BatchFunction& f, double at_most, double closest) {
  std::vector<std::pair<double, double>> minima;
  const std::size_t n = xs.size();
  for (std::size_t i = 0; i < n; ++i) {
    const bool left = i == 0 || values[i] <= values[i - 1];
    const bool right = i + 1 == n || values[i] < values[i + 1];
    if (!left || !right) continue;
    // To the higher neighbour: the bottom lies at most that far below the sample.
    const double rise = std::max(i > 0 ? values[i - 1] : values[i], i + 1 < n ? values[i + 1] : values[i]) - values[i];
    if (values[i] - rise > at_most) continue;
    std::pair<double, double> best{xs[i], values[i]};
    if (i == 0 || i + 1 == n) {
      if (n > 1) best = towards_the_end(f, xs[i], values[i], xs[i == 0 ? 1 : n - 2], closest);
    } else {
      const auto refined = brent(f, xs[i - 1], xs[i + 1]);
      if (refined.second < best.second) best = refined;
    }
    minima.push_back(best);
  }
  return minima;
}

double highest_sampled_pressure(const ContactSolution& s) {
  std::vector<double> highest(s.zone_count(), 0.0);
  for_each_index(s.zone_count(), zones_for_threads, [&](std::size_t k) {
    for (double p : s.sampled_pressure(k).ps) highest[k] = std::max(highest[k], p);
  });
  return highest.empty() ? 0.0 : *std::max_element(highest.begin(), highest.end());
}

namespace {

// One zone's pressure: its highest sample (the first, if equal) and its local minima.
struct ZoneCheck {
  double highest = 0, x_of_highest = 0;
  std::vector<std::pair<double, double>> minima;
};

ZoneCheck check_zone(const ContactSolution& s, std::size_t k) {
  ZoneCheck check;
  const auto& [xs, ps] = s.sampled_pressure(k);
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (ps[i] > check.highest) check.highest = ps[i], check.x_of_highest = xs[i];
  }
  // Only a minimum that may fall below 0 can be a tension, or the lowest pressure reported.
  // Between an end and the node next to it, the zone's series is held by the end condition
  // alone: a zone of 4096 nodes ending 2.4e-5 past a kink showed a wiggle 1e-8 from its end,
  // a quarter of that node's distance, and settling cut it as a tension 44 times over
  // (campaign seed 12, sweep 55 with 100 loads).
  const ZoneGeometry& g = s.zone(k);
  const double c = std::cos(pi / (2.0 * static_cast<double>(s.configuration().zones[k].d.size())));
  const std::vector<double> first = g.angles_of({c, -c});  // the nodes next to a and to b
  const double closest = std::min(first[0] - g.a, g.b - first[1]);
  check.minima = local_minima(
      xs, ps, [&](const double* x, double* p, std::size_t count) { s.pressures(x, p, count); }, 0.0, closest);
  return check;
}

// One stretch [lo, hi] between zones: the gap's local minima and those that penetrate.
struct GapCheck {
  std::vector<std::pair<double, double>> minima;
  std::vector<Penetration> penetrations;
};

GapCheck check_gap(const ContactSolution& s, double lo, double hi, double gap_tolerance) {
  GapCheck check;
  if (!(hi > lo)) return check;
  const SurfaceModel& surface = s.surface();
  const double spacing = surface.resolution / 8;
  const int count = std::max(8, static_cast<int>(std::ceil((hi - lo) / spacing)));
  std::vector<double> xs;
  for (int i = 0; i <= count; ++i) {
    // Chebyshev-like near the zone ends (the gap grows like a 3/2 power there), even inside.
    const double t = static_cast<double>(i) / count;
    const double x = lo + (hi - lo) * (0.5 - 0.5 * std::cos(pi * t)) * 0.25 + (hi - lo) * t * 0.75;
    xs.push_back(std::clamp(x, lo, hi));
  }
  std::vector<double> gaps(xs.size());
  s.gaps(xs.data(), gaps.data(), xs.size());
  // Only a minimum that may fall below 0 can penetrate, or be the lowest gap reported.
  check.minima = local_minima(
      xs, gaps, [&](const double* x, double* g, std::size_t count) { s.gaps(x, g, count); }, 0.0);
  const double step = 1e-3 * surface.resolution;
  for (auto& [x, value] : check.minima) {
    // The gap is even about the top and the valley: a minimum within a thousandth of the
    // resolution of either is that one (probed up to it, the lowest probe may lie a rounding
    // away, and a new zone there runs through it).
    if (lo == 0 && x < step) x = 0;
    if (hi == pi && pi - x < step) x = pi;
    // The gap grows like the 3/2 power of the distance from a zone's end: a shallow dip
    // right next to one is the truncation of that zone's series, not a new contact.
    const double from_end = std::min(lo > 0 ? x - lo : pi, hi < pi ? hi - x : pi);
    const bool beside_an_end = from_end < 1e-3 * (hi - lo) && value > -1e-6 * surface.height_range;
    if (value < -gap_tolerance && !beside_an_end) {
      // The second difference over a thousandth of the resolution, the gap taken even about
      // the top and the valley, short of the zones' ends.
      const double h = std::min({step, lo > 0 ? (x - lo) / 2 : step, hi < pi ? (hi - x) / 2 : step});
      const auto even = [&](double y) { return s.gap(y > pi ? 2 * pi - y : y); };
      const double curvature = h > 0 ? (even(x + h) - 2 * value + even(x - h)) / (h * h) : 0;
      check.penetrations.push_back({x, value, curvature, lo, hi});
    }
  }
  return check;
}

}  // namespace

Verification verify(const ContactSolution& s, double gap_tolerance, double pressure_tolerance) {
  // The zones, and the stretches between them (and to the top and the valley), each checked
  // on its own by the threads, and the results taken in order.
  const std::size_t zones = s.zone_count();
  std::vector<ZoneCheck> zone_checks(zones);
  std::vector<GapCheck> gap_checks(zones + 1);
  for_each_index(2 * zones + 1, zones_for_threads, [&](std::size_t i) {
    if (i < zones) {
      zone_checks[i] = check_zone(s, i);
    } else {
      const std::size_t k = i - zones;  // the stretch before zone k
      gap_checks[k] = check_gap(s, k == 0 ? 0.0 : s.zone(k - 1).b, k == zones ? pi : s.zone(k).a, gap_tolerance);
    }
  });
  Verification v;
  for (std::size_t k = 0; k < zones; ++k) {
    const ZoneCheck& z = zone_checks[k];
    if (z.highest > v.highest_pressure) v.highest_pressure = z.highest, v.x_of_highest_pressure = z.x_of_highest;
    for (const auto& [x, value] : z.minima) {
      if (value < v.lowest_pressure) v.lowest_pressure = value, v.x_of_lowest_pressure = x;
      if (value < 0) v.tensions.push_back({k, x, value, 0.0});
    }
  }
  // A narrow gap's edges, where its pressure rises like a root over a width far below the
  // zone's samples, probed at geometric distances from each; and its gap inside.
  for (std::size_t k = 0; k < zones; ++k) {
    for (const NarrowGap& g : s.narrow_gaps(k)) {
      for (double side : {-1.0, 1.0}) {
        for (int j = -10; j <= 30; ++j) {
          const double x = g.centre + side * g.half * (1 + std::ldexp(1.0, -j)), value = s.pressure(x);
          if (value < v.lowest_pressure) v.lowest_pressure = value, v.x_of_lowest_pressure = x;
          if (value < 0) v.tensions.push_back({k, x, value, 0.0});
        }
      }
      for (int i = 1; i < 32; ++i) {
        const double x = g.centre - g.half * std::cos(pi * i / 32), value = s.gap(x);
        if (value < v.lowest_gap) v.lowest_gap = value, v.x_of_lowest_gap = x;
        if (value < -gap_tolerance) v.penetrations.push_back({x, value, 0.0, g.centre - g.half, g.centre + g.half});
      }
    }
  }
  const double allowed = -pressure_tolerance * v.highest_pressure;
  v.tensions.erase(
      std::remove_if(v.tensions.begin(), v.tensions.end(), [&](const Tension& t) { return !(t.pressure < allowed); }),
      v.tensions.end());
  v.pressure_ok = v.tensions.empty();
  for (Tension& t : v.tensions) {
    const ZoneGeometry& zone = s.zone(t.zone);
    const double h = std::min({1e-3 * s.surface().resolution, (t.x - zone.a) / 2, (zone.b - t.x) / 2});
    const double curvature = h > 0 ? (s.pressure(t.x + h) - 2 * t.pressure + s.pressure(t.x - h)) / (h * h) : 0.0;
    t.curvature = curvature > 0 ? curvature : 0.0;
  }
  for (const GapCheck& g : gap_checks) {
    for (const auto& [x, value] : g.minima) {
      if (value < v.lowest_gap) v.lowest_gap = value, v.x_of_lowest_gap = x;
    }
    v.penetrations.insert(v.penetrations.end(), g.penetrations.begin(), g.penetrations.end());
  }
  return v;
}

}  // namespace wavecontact::detail
