#include "solution.hpp"

#include <algorithm>
#include <cmath>

#include "constants.hpp"
#include "support/parallel.hpp"
#include "zone_field.hpp"

namespace wavecontact::detail {

namespace {

// A run of points in one zone is summed in batches of this many (held on the stack).
constexpr std::size_t pressure_batch = 64;
// Points times the longest zone's series above which pressures() shares its points out to the
// threads: a zone across a kink holds thousands of nodes, and each point sums them all (the
// 200 loads of the wave curve m = 10 compared 801 samples on 8192 nodes in its refinement).
constexpr std::size_t parallel_pressure_terms = std::size_t{1} << 18;

}  // namespace

ContactSolution::ContactSolution(std::shared_ptr<const SurfaceModel> surface, Configuration configuration)
    : surface_(std::move(surface)),
      configuration_(std::move(configuration)),
      fields_(*surface_, configuration_),
      samples_(2 * configuration_.zones.size()),
      sampled_(std::make_unique<std::once_flag[]>(2 * configuration_.zones.size())) {
  for (const ZoneUnknowns& z : configuration_.zones) {
    ends_.push_back(z.geometry.a), ends_.push_back(z.geometry.b);
    pressure_series_.push_back(bounded_pressure_series(z.geometry, z.d.data(), static_cast<int>(z.d.size())));
    longest_series_ = std::max(longest_series_, pressure_series_.back().size());
  }
  // Each narrow gap from the merged pressure, its derivatives by differences of a thousandth
  // of the resolution (their truncation about 1e-6 of the curvature).
  narrow_.resize(zone_count());
  for (double x : configuration_.narrow_gaps) {
    const std::size_t k = zone_at(x);
    if (k == zone_count()) continue;
    const std::optional<NarrowGap> g =
        narrow_gap([&](double t) { return merged_pressure(k, t); }, x, 1e-3 * surface_->resolution);
    if (g && g->centre - g->half > zone(k).a && g->centre + g->half < zone(k).b) narrow_[k].push_back(*g);
  }
  for (std::vector<NarrowGap>& gaps : narrow_) {
    std::sort(gaps.begin(), gaps.end(), [](const NarrowGap& l, const NarrowGap& r) { return l.centre < r.centre; });
  }
}

bool ContactSolution::full_contact() const { return zone_count() == 1 && zone(0).top() && zone(0).valley(); }

std::size_t ContactSolution::zone_at(double x) const {
  // The first end above x: inside a zone when it is the zone's b (odd position).
  const auto it = std::lower_bound(ends_.begin(), ends_.end(), x);
  if (it == ends_.end()) return zone_count();
  const std::size_t i = static_cast<std::size_t>(it - ends_.begin());
  if (i % 2 == 1 || *it == x) return i / 2;
  return zone_count();
}

double ContactSolution::pressure(double x) const {
  double p = 0;
  pressures(&x, &p, 1);
  return p;
}

void ContactSolution::pressures(const double* xs, double* ps, std::size_t count) const {
  // Each point is summed alone (chebyshev.cpp, zone_field.cpp), so how the points are shared
  // out does not change a bit.
  if (count > pressure_batch && count * longest_series_ >= parallel_pressure_terms) {
    for_each_chunk(count, pressure_batch, 0,
                   [&](std::size_t begin, std::size_t end) { pressures_here(xs + begin, ps + begin, end - begin); });
  } else {
    pressures_here(xs, ps, count);
  }
}

void ContactSolution::pressures_here(const double* xs, double* ps, std::size_t count) const {
  // Each run of points in one zone takes one batch of the zone's sums (a single point
  // allocates nothing).
  double run[pressure_batch];
  for (std::size_t i = 0; i < count;) {
    const std::size_t k = zone_at(std::fabs(xs[i]));
    std::size_t end = i + 1;
    while (end < count && end - i < pressure_batch && zone_at(std::fabs(xs[end])) == k) ++end;
    if (k == zone_count()) {
      std::fill(ps + i, ps + end, 0.0);
    } else {
      for (std::size_t j = i; j < end; ++j) run[j - i] = std::fabs(xs[j]);
      const ZoneGeometry& g = zone(k);
      zone_pressures(g, pressure_series_[k], run, ps + i, end - i);
      for (std::size_t j = i; j < end; ++j) {
        const double x = run[j - i];
        if ((x == g.a && !g.top()) || (x == g.b && !g.valley())) {
          ps[j] = 0;  // a free end
          continue;
        }
        ps[j] += kink_pressure(k, x);
        for (const NarrowGap& gap : narrow_[k]) {
          if (gap.inside(x)) {
            ps[j] = 0;
            break;
          }
          ps[j] += gap.correction(x);
        }
      }
    }
    i = end;
  }
}

double ContactSolution::merged_pressure(std::size_t k, double x) const {
  double p = 0;
  zone_pressures(zone(k), pressure_series_[k], &x, &p, 1);
  return p + kink_pressure(k, x);
}

double ContactSolution::kink_pressure(std::size_t k, double x) const {
  return fields_.kinks[k] ? std::sin(x) * fields_.kinks[k]->density(std::cos(x)) : 0.0;
}

double ContactSolution::potential(double x) const { return fields_.potential(x, zone_count()); }

double ContactSolution::gap_in_zone(std::size_t k, double x) const {
  for (const NarrowGap& g : narrow_[k]) {
    if (g.inside(x)) return g.gap(x, surface_->E);
  }
  return 0;
}

double ContactSolution::gap(double x) const {
  x = std::fabs(x);
  if (const std::size_t k = zone_at(x); k != zone_count()) return gap_in_zone(k, x);
  return gap_of(potential(x) - configuration_.C, surface_->depth(x));
}

void ContactSolution::gaps(const double* xs, double* gs, std::size_t count) const {
  std::vector<double> off;
  std::vector<std::size_t> at;
  for (std::size_t i = 0; i < count; ++i) {
    const double x = std::fabs(xs[i]);
    const std::size_t k = zone_at(x);
    gs[i] = k == zone_count() ? 0.0 : gap_in_zone(k, x);
    if (k == zone_count()) off.push_back(x), at.push_back(i);
  }
  if (off.empty()) return;
  const FieldTree::Batch field = fields_.evaluate(zone_count(), off, off[off.size() / 2], false);
  std::vector<double> depth(off.size());
  surface_->height_differences(off.data(), off.size(), surface_->top_angle, depth.data());
  const double offset = field.at_reference - configuration_.C;
  for (std::size_t j = 0; j < off.size(); ++j) gs[at[j]] = gap_of(offset + field.difference[j], depth[j]);
}

int ContactSolution::pressure_samples(std::size_t k) const {
  const ZoneGeometry& g = zone(k);
  const double features = 256 + 8 * std::ceil((g.b - g.a) / surface_->resolution);
  const double nodes = static_cast<double>(configuration_.zones[k].d.size());
  return 3 * static_cast<int>(std::min(nodes, features)) + 8;
}

const ContactSolution::PressureSamples& ContactSolution::sampled_pressure(std::size_t k, Span span) const {
  const std::size_t at = 2 * k + (span == Span::inside ? 1 : 0);
  std::call_once(sampled_[at], [&] {
    const ZoneGeometry& g = zone(k);
    const int count = pressure_samples(k);
    PressureSamples& s = samples_[at];
    const double margin = span == Span::inside ? 0.01 * (g.b - g.a) : 0.0;
    const double lo = g.top() ? g.a : g.a + margin, hi = g.valley() ? g.b : g.b - margin;
    for (int i = 0; i <= count; ++i)
      s.xs.push_back(std::clamp((lo + hi) / 2 - (hi - lo) / 2 * std::cos(pi * i / count), g.a, g.b));
    s.ps.resize(s.xs.size());
    pressures(s.xs.data(), s.ps.data(), s.xs.size());
  });
  return samples_[at];
}

double ContactSolution::zone_load(std::size_t k) const { return detail::zone_load(configuration_, fields_, k); }

double ContactSolution::load() const {
  double sum = 0;
  for (std::size_t k = 0; k < zone_count(); ++k) sum += 2 * zone_load(k);
  return sum;
}

}  // namespace wavecontact::detail
