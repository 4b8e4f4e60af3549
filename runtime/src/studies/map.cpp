#include "wavecontact/map.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>

#include <boost/math/constants/constants.hpp>

#include "support/validate.hpp"
#include "support/worker_pool.hpp"
#include "wavecontact/errors.hpp"
#include "wavecontact/two_scale.hpp"

namespace wavecontact {

namespace {

using boost::math::double_constants::pi;

std::size_t at_least_one(std::size_t count) { return std::max<std::size_t>(count, 1); }

MapPoint point_of(const MapGrid& grid, std::size_t line, std::size_t load) {
  MapPoint p;
  p.index = line * grid.loads.size() + load;
  p.m = grid.line_m(line);
  p.harmonics = grid.line_roughness(line);
  p.H2 = p.harmonics.size() == 1 ? p.harmonics.front().H
         : p.harmonics.empty()   ? 0.0
                                 : std::numeric_limits<double>::quiet_NaN();
  p.n = p.harmonics.size() == 1 ? p.harmonics.front().n : 0;
  const double pstar_load = pi * grid.waviness.E * grid.waviness.H1;  // P at pa/p* = 1
  p.P = grid.loads_are_ratios ? grid.loads[load] * pstar_load : grid.loads[load];
  p.pa_over_pstar = grid.loads_are_ratios ? grid.loads[load] : grid.loads[load] / pstar_load;
  return p;
}

void record(MapPoint& p, const Contact& c, double tolerance) {
  p.status = c.error_estimate() <= tolerance ? MapStatus::solved : MapStatus::above_tolerance;
  p.zones = c.zones_per_period();
  p.contact_fraction = c.contact_fraction();
  p.p0 = c.pressure(0);
  p.max_p = c.max_pressure();
  p.error_estimate = c.error_estimate();
}

void record_beyond_reach(MapPoint& p, const std::string& why) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  p.status = MapStatus::beyond_reach;
  p.zones = 0;
  p.contact_fraction = p.p0 = p.max_p = p.error_estimate = nan;
  p.message = why;
}

}  // namespace

std::size_t MapGrid::roughness_count() const {
  return harmonics.empty() ? at_least_one(H2.size()) * at_least_one(n.size()) : harmonics.size();
}

std::size_t MapGrid::line_count() const { return at_least_one(m.size()) * roughness_count(); }

double MapGrid::line_m(std::size_t line) const { return m.empty() ? waviness.m : m[line / roughness_count()]; }

std::vector<Harmonic> MapGrid::line_roughness(std::size_t line) const {
  const std::size_t r = line % roughness_count();
  if (!harmonics.empty()) return harmonics[r];
  if (H2.empty()) return {};
  return {{H2[r / n.size()], n[r % n.size()]}};
}

// The zones, and with them a line's time, grow with the roughness's n and height (the
// bench's map: 0.02 s a line at n = 8 against 0.22 s at n = 32, H2 = 0.02); the longest
// lines started first leave no long one running alone at the end (the bench's map, 2 cores:
// 3.59 -> 3.51 s wall).
std::vector<std::size_t> MapGrid::lines_costliest_first() const {
  std::vector<double> finest(line_count()), height(line_count());
  std::vector<std::size_t> order(line_count());
  for (std::size_t line = 0; line < order.size(); ++line) {
    order[line] = line;
    for (const Harmonic& h : line_roughness(line)) {
      finest[line] = std::max(finest[line], static_cast<double>(h.n));
      height[line] += std::fabs(h.H);
    }
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return finest[a] != finest[b] ? finest[a] > finest[b] : height[a] > height[b];
  });
  return order;
}

const char* to_string(MapStatus status) {
  switch (status) {
    case MapStatus::solved:
      return "solved";
    case MapStatus::above_tolerance:
      return "above_tolerance";
    case MapStatus::beyond_reach:
      return "beyond_reach";
  }
  return "?";
}

void validate(const MapGrid& grid, const char* function) {
  for (double m : grid.m.empty() ? std::vector<double>{grid.waviness.m} : grid.m) {
    WavinessParams w = grid.waviness;
    w.m = m;
    validate(w, function);
  }
  if (grid.H2.empty() != grid.n.empty()) {
    detail::domain_error(function, grid.H2.empty() ? "n.size()" : "H2.size()",
                         static_cast<double>(std::max(grid.H2.size(), grid.n.size())),
                         "0 with no roughness, else at least one H2 and one n");
  }
  for (double H2 : grid.H2) {
    for (int n : grid.n) validate(RoughnessParams{H2, n}, function);
  }
  if (!grid.harmonics.empty() && !grid.H2.empty()) {
    detail::domain_error(function, "harmonics.size()", static_cast<double>(grid.harmonics.size()),
                         "0 with H2 and n (the roughnesses are either H2 x n or the list harmonics)");
  }
  for (const std::vector<Harmonic>& roughness : grid.harmonics) {
    if (roughness.empty()) detail::domain_error(function, "harmonics[i].size()", 0, "at least one harmonic");
    validate(roughness, function);
  }
  if (grid.loads.empty()) detail::domain_error(function, "loads.size()", 0, "at least one load");
  for (std::size_t i = 0; i < grid.loads.size(); ++i) {
    detail::require_positive(function, "load", grid.loads[i]);
    if (i > 0 && !(grid.loads[i] > grid.loads[i - 1])) {
      detail::domain_error(function, "load", grid.loads[i],
                           "ascending: above the load before it, " + detail::format(grid.loads[i - 1]));
    }
  }
}

std::vector<MapPoint> solve_map_line(const MapGrid& grid, std::size_t line, const SolverOptions& options) {
  std::vector<MapPoint> points;
  for (std::size_t k = 0; k < grid.loads.size(); ++k) points.push_back(point_of(grid, line, k));
  WavinessParams w = grid.waviness;
  w.m = grid.line_m(line);
  const Surface surface(w, grid.line_roughness(line));
  std::vector<double> loads;
  for (const MapPoint& p : points) loads.push_back(p.P);
  try {
    const std::vector<Contact> contacts = solve_contact(surface, loads, options);
    for (std::size_t k = 0; k < points.size(); ++k) record(points[k], contacts[k], options.tolerance);
  } catch (const BeyondReach&) {
    // The continuation stopped at one load: each load alone, so that the others are solved.
    for (MapPoint& p : points) {
      try {
        record(p, solve_contact(surface, p.P, options), options.tolerance);
      } catch (const BeyondReach& e) {
        record_beyond_reach(p, e.what());
      }
    }
  }
  return points;
}

void map_contacts(const MapGrid& grid, const MapOptions& options, const std::function<bool(std::size_t)>& skip,
                  const std::function<void(const std::vector<MapPoint>&)>& line_done) {
  validate(grid, "wavecontact::map_contacts");
  const std::size_t lines = grid.line_count();
  const unsigned threads = static_cast<unsigned>(std::min<std::size_t>(
      lines, options.threads > 0 ? options.threads : std::max(1u, std::thread::hardware_concurrency())));
  const std::vector<std::size_t> order = grid.lines_costliest_first();
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex done_mutex;
  std::exception_ptr failure;
  const auto work = [&] {
    // The lines keep the cores busy: each solve's own parallel calls on its thread alone.
    const detail::WorkerPoolBypass alone(threads > 1);
    for (;;) {
      const std::size_t taken = next++;
      if (taken >= lines || stop) return;
      const std::size_t line = order[taken];
      try {
        if (skip && skip(line)) continue;
        const std::vector<MapPoint> points = solve_map_line(grid, line, options.solver);
        const std::lock_guard<std::mutex> lock(done_mutex);
        if (!stop) line_done(points);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(done_mutex);
        if (!failure) failure = std::current_exception();
        stop = true;
      }
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace wavecontact
