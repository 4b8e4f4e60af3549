#include "verification.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include <boost/math/tools/minima.hpp>

#include "chebyshev.hpp"
#include "constants.hpp"

namespace wavecontact::detail {

std::vector<std::pair<double, double>> local_minima(const std::vector<double>& xs, const std::vector<double>& values,
                                                    const std::function<double(double)>& f, double at_most) {
  std::vector<std::pair<double, double>> minima;
  const std::size_t n = xs.size();
  for (std::size_t i = 0; i < n; ++i) {
    const bool left = i == 0 || values[i] <= values[i - 1];
    const bool right = i + 1 == n || values[i] < values[i + 1];
    if (!left || !right || values[i] > at_most) continue;
    std::pair<double, double> best{xs[i], values[i]};
    const double a = i > 0 ? xs[i - 1] : xs[i], b = i + 1 < n ? xs[i + 1] : xs[i];
    if (b > a) {
      const auto [x, v] = boost::math::tools::brent_find_minima(f, a, b, 40);
      if (v < best.second) best = {x, v};
    }
    minima.push_back(best);
  }
  return minima;
}

namespace {

// The pressure on zone k at its samples: 3 M + 8 points spread like Chebyshev's.
void sample_pressure(const ContactSolution& s, std::size_t k, std::vector<double>& xs, std::vector<double>& ps) {
  const ZoneGeometry& g = s.zone(k);
  const int count = s.pressure_samples(k);
  xs.clear(), ps.clear();
  for (int i = 0; i <= count; ++i) {
    const double x = (g.a + g.b) / 2 - (g.b - g.a) / 2 * std::cos(pi * i / count);
    xs.push_back(std::clamp(x, g.a, g.b));
    ps.push_back(s.pressure(xs.back()));
  }
}

}  // namespace

double highest_sampled_pressure(const ContactSolution& s) {
  double highest = 0;
  std::vector<double> xs, ps;
  for (std::size_t k = 0; k < s.zone_count(); ++k) {
    sample_pressure(s, k, xs, ps);
    for (double p : ps) highest = std::max(highest, p);
  }
  return highest;
}

Verification verify(const ContactSolution& s, double gap_tolerance, double pressure_tolerance) {
  Verification v;
  const SurfaceModel& surface = s.surface();
  std::vector<double> xs, ps;
  for (std::size_t k = 0; k < s.zone_count(); ++k) {
    sample_pressure(s, k, xs, ps);
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (ps[i] > v.highest_pressure) v.highest_pressure = ps[i], v.x_of_highest_pressure = xs[i];
    }
    const auto p = [&](double x) { return s.pressure(x); };
    for (const auto& [x, value] : local_minima(xs, ps, p)) {
      if (value < v.lowest_pressure) v.lowest_pressure = value, v.x_of_lowest_pressure = x;
      if (value < 0) v.tensions.push_back({k, x, value});
    }
  }
  const double allowed = -pressure_tolerance * v.highest_pressure;
  v.tensions.erase(
      std::remove_if(v.tensions.begin(), v.tensions.end(), [&](const Tension& t) { return !(t.pressure < allowed); }),
      v.tensions.end());
  v.pressure_ok = v.tensions.empty();
  // The gap on each stretch between zones (and to the top and the valley).
  std::vector<std::pair<double, double>> regions;
  double previous = 0;
  for (std::size_t k = 0; k < s.zone_count(); ++k) {
    regions.emplace_back(previous, s.zone(k).a);
    previous = s.zone(k).b;
  }
  regions.emplace_back(previous, pi);
  const double spacing = surface.resolution / 8;
  for (const auto& [lo, hi] : regions) {
    if (!(hi > lo)) continue;
    const int count = std::max(8, static_cast<int>(std::ceil((hi - lo) / spacing)));
    std::vector<double> xs, gaps;
    for (int i = 0; i <= count; ++i) {
      // Chebyshev-like near the zone ends (the gap grows like a 3/2 power there), even inside.
      const double t = static_cast<double>(i) / count;
      const double x = lo + (hi - lo) * (0.5 - 0.5 * std::cos(pi * t)) * 0.25 + (hi - lo) * t * 0.75;
      xs.push_back(std::clamp(x, lo, hi));
      gaps.push_back(s.gap(xs.back()));
    }
    const auto gap = [&](double x) { return s.gap(x); };
    for (const auto& [x, value] : local_minima(xs, gaps, gap)) {
      if (value < v.lowest_gap) v.lowest_gap = value, v.x_of_lowest_gap = x;
      // The gap grows like the 3/2 power of the distance from a zone's end: a shallow dip
      // right next to one is the truncation of that zone's series, not a new contact.
      const double from_end = std::min(lo > 0 ? x - lo : pi, hi < pi ? hi - x : pi);
      const bool beside_an_end = from_end < 1e-3 * (hi - lo) && value > -1e-6 * surface.height_range;
      if (value < -gap_tolerance && !beside_an_end) {
        const double h = std::min({1e-3 * surface.resolution, (x - lo) / 2, (hi - x) / 2});
        const double curvature = h > 0 ? (s.gap(x + h) - 2 * value + s.gap(x - h)) / (h * h) : 0;
        v.penetrations.push_back({x, value, curvature, lo, hi});
      }
    }
  }
  return v;
}

}  // namespace wavecontact::detail
