#include "active_set.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "constants.hpp"
#include "kink_correction.hpp"
#include "solution.hpp"
#include "trace.hpp"
#include "verification.hpp"
#include "zone_system.hpp"

namespace wavecontact::detail {

namespace {

constexpr double working_tail = 1e-9;  // of a zone's coefficients: beyond, more nodes
// Of a zone's width, or of the resolution (half the shortest wavelength) if that is less: a
// zone over many asperities keeps the asperities beside a cut.
constexpr double cut_margin = 0.1;       // left out around a cut
constexpr double shortest_piece = 0.02;  // a shorter piece is dropped
constexpr double returning = 0.01;       // a tension this near a place cut before returns

// At least the nodes a zone's width asks for: four a half wavelength of the shortest harmonic
// on top of the 16 of a cap, so that the density of a zone that spans several asperities is
// resolved before Newton's method meets it; and for a zone across a kink, eight for each
// window radius of its extent in s, so that the window's edges are resolved (coarser, the
// collocation has roots with the ends far from the contact's). With near_neighbours, also
// for a zone whose end lies a distance g from the next zone's (or from its own mirror image
// beyond the top or the valley), 12 sqrt(width / g): the neighbour's density, which falls like
// a root at its end, gives this zone's right-hand side a branch point g beyond its end, where
// Chebyshev series converge like exp(-2 N sqrt(g / width)); coarser, Newton's method can
// stall as two zones nearly touch. Asked for only where it did (a zone keeps its nodes
// through the later loads of a sweep). Whether any zone grew.
std::size_t width_nodes(const ZoneUnknowns& z, const SurfaceModel& surface) {
  const double halves = (z.geometry.b - z.geometry.a) / surface.resolution;
  std::size_t needed = static_cast<std::size_t>(working_nodes + 8 * std::ceil(halves / 2));
  const double r = KinkCorrection::radius_for(surface, z.geometry);
  if (r > 0)
    needed = std::max(needed,
                      static_cast<std::size_t>(8 * std::ceil((std::cos(z.geometry.a) - std::cos(z.geometry.b)) / r)));
  return needed;
}

// The nodes zone k's nearest neighbour asks for, 12 sqrt(width / g) (width_nodes); 0 with
// none (a gap of 0 closes as a stretch first).
double neighbour_nodes(const Configuration& c, std::size_t k) {
  const ZoneGeometry& z = c.zones[k].geometry;
  const double before = k == 0 ? 2 * z.a : z.a - c.zones[k - 1].geometry.b;
  const double after = k + 1 == c.zones.size() ? 2 * (pi - z.b) : c.zones[k + 1].geometry.a - z.b;
  const double nearest = std::min(z.a > 0 ? before : pi, z.b < pi ? after : pi);
  return nearest > 0 ? 12 * std::sqrt((z.b - z.a) / nearest) : 0.0;
}

// Whether two zones, or a zone and its mirror image, lie nearer than the most working nodes
// resolve: such a contact may be a root of the coarse equations alone.
bool crowded(const Configuration& c) {
  for (std::size_t k = 0; k < c.zones.size(); ++k) {
    if (!(neighbour_nodes(c, k) <= most_working_nodes)) return true;
  }
  return false;
}

bool fit_nodes(Configuration& c, const SurfaceModel& surface, bool near_neighbours = false,
               const std::function<bool(const ZoneUnknowns&)>& where = {}) {
  bool grown = false;
  for (std::size_t k = 0; k < c.zones.size(); ++k) {
    ZoneUnknowns& z = c.zones[k];
    if (where && !where(z)) continue;
    std::size_t needed = width_nodes(z, surface);
    if (near_neighbours) {
      // The count bounded before its conversion.
      const double near_nodes = neighbour_nodes(c, k);
      needed = near_nodes < most_working_nodes ? std::max(needed, static_cast<std::size_t>(std::ceil(near_nodes)))
                                               : static_cast<std::size_t>(most_working_nodes);
    }
    if (z.d.size() < std::min<std::size_t>(most_working_nodes, needed)) {
      z.d.resize(std::min<std::size_t>(most_working_nodes, needed), 0.0);
      grown = true;
    }
  }
  return grown;
}

// Twice the nodes (at most most_working_nodes) for a zone whose tail exceeds `limit` and its
// rows' rounding (row_rounding: a small zone's coefficients converge no further), or for
// every zone `where` holds; whether any grew.
bool grow_nodes(Configuration& c, const SurfaceModel& surface, double limit,
                const std::function<bool(const ZoneUnknowns&)>& where = {}) {
  bool grown = false;
  const std::vector<double> rounding = row_rounding(surface, c);
  for (std::size_t k = 0; k < c.zones.size(); ++k) {
    ZoneUnknowns& z = c.zones[k];
    const bool wanted = where ? where(z) : true;
    const double floor = 10 * rounding[k] / std::max(own_potential(z), std::numeric_limits<double>::min());
    if (wanted && coefficient_tail(z.d) > std::max(limit, floor) &&
        z.d.size() < static_cast<std::size_t>(most_working_nodes)) {
      z.d.resize(std::min<std::size_t>(most_working_nodes, 2 * z.d.size()), 0.0);
      grown = true;
    }
  }
  return grown;
}

// Twice the nodes, beyond most_working_nodes up to most_kinked_nodes, for each zone with a
// tension whose kink window its nodes do not resolve (window_unresolved); whether any grew.
// Such a tension may be the series' own wiggle: a top zone ending 6.7e-5 past the kink of the
// near-square wave m = 121.6 (window 3.2e-5, 11 of its 4096 nodes within it; n = 198 and 140,
// P = 102.38, campaign seed 62, sweep 9 with 16 loads) showed -0.168 next to its end, and cut,
// came back with it 400 times; on 8192 nodes it has none.
bool grow_unresolved_windows(Configuration& c, const SurfaceModel& surface, const std::vector<Tension>& tensions) {
  bool grown = false;
  for (std::size_t k = 0; k < c.zones.size(); ++k) {
    ZoneUnknowns& z = c.zones[k];
    const bool tense = std::any_of(tensions.begin(), tensions.end(), [&](const Tension& t) { return t.zone == k; });
    if (tense && z.d.size() < static_cast<std::size_t>(most_kinked_nodes) && window_unresolved(surface, z)) {
      z.d.resize(2 * z.d.size(), 0.0);
      grown = true;
    }
  }
  return grown;
}

ZoneUnknowns zone_of(double a, double b, std::size_t nodes) {
  return {ZoneGeometry(a, b), std::vector<double>(nodes, 0.0)};
}

void insert_zone(Configuration& c, ZoneUnknowns z) {
  const auto at = std::lower_bound(c.zones.begin(), c.zones.end(), z.geometry.a,
                                   [](const ZoneUnknowns& u, double a) { return u.geometry.a < a; });
  c.zones.insert(at, std::move(z));
}

// The stretch between ends e and e + 1 of [0, a_0, b_0, ..., pi] closes.
bool close_stretch(Configuration& c, std::size_t e) {
  const std::size_t last = 2 * c.zones.size();
  if (e == 0) {
    c.zones.front().geometry = ZoneGeometry(0, c.zones.front().geometry.b);
  } else if (e == last) {
    c.zones.back().geometry = ZoneGeometry(c.zones.back().geometry.a, pi);
  } else if (e % 2 == 1) {  // zone (e - 1)/2 vanishes
    c.zones.erase(c.zones.begin() + static_cast<std::ptrdiff_t>((e - 1) / 2));
  } else {  // the gap between zones e/2 - 1 and e/2 closes: they merge
    const std::size_t k = e / 2 - 1;
    const std::size_t nodes = std::max(c.zones[k].d.size(), c.zones[k + 1].d.size());
    c.zones[k] = zone_of(c.zones[k].geometry.a, c.zones[k + 1].geometry.b, nodes);
    c.zones.erase(c.zones.begin() + static_cast<std::ptrdiff_t>(k) + 1);
  }
  return !c.zones.empty();
}

// Zones whose gap is narrower than a millionth of the resolution merge: no profile smooth on
// the scale of its resolution separates two contacts by so little, and such a gap is one
// zone's end (campaign seed 97, sweep 141: a sliver 6.6e-9 wide 1.6e-8 past a zone's end,
// which the refinement's Newton method could not solve). Whether any merged.
bool merge_close_zones(Configuration& c, double resolution) {
  bool merged = false;
  for (std::size_t k = c.zones.size(); k-- > 1;) {
    if (c.zones[k].geometry.a - c.zones[k - 1].geometry.b < 1e-6 * resolution) {
      close_stretch(c, 2 * k);
      merged = true;
    }
  }
  return merged;
}

// A new zone at each penetration: about the width of the region where the gap is below 0
// (the gap near its lowest point is depth + curvature (x - x0)^2 / 2), a quarter of the room
// around it at most; at the top or the valley it runs through it.
void open_zones(Configuration& c, const std::vector<Penetration>& penetrations, double resolution) {
  for (const Penetration& p : penetrations) {
    const double below = p.curvature > 0 ? std::sqrt(2 * -p.depth / p.curvature) : resolution / 4;
    const double room = p.x == 0 ? p.hi - p.x : p.x == pi ? p.x - p.lo : std::min(p.x - p.lo, p.hi - p.x);
    const double w = std::min(0.5 * below, 0.25 * room);
    if (!(w > 0)) continue;
    insert_zone(c, p.x - w <= 0    ? zone_of(0, p.x + w, working_nodes)
                   : p.x + w >= pi ? zone_of(p.x - w, pi, working_nodes)
                                   : zone_of(p.x - w, p.x + w, working_nodes));
  }
}

// Each zone with a negative pressure is cut at every such point: the pieces around the cuts,
// less a margin, those long enough kept (a piece at the top or the valley keeps it), each
// with its share of the zone's nodes. The margin is a tenth of the zone's width or of the
// resolution, or where the pressure's dip is narrower and well inside the zone (a tenth of
// its distance from a free end), the half-width of the stretch where its parabola (depth and
// curvature at the minimum) is below 0. (Next to an end, that parabola's 7e-8 cut the zone
// back by as little, and the same tension came back 400 times: the wave curve m = 20 with
// n = 22, 14 and 2, campaign seed 25, sweep 85 with 32 loads.) Near full contact a dip of
// 5e-5 of the largest pressure next to the kink of the wave curve m = 17.6 (n = 6 and 10,
// campaign seed 5, sweep 127 with 64 loads, --max-n 32) opens a gap of 6.3e-4, which Newton's
// method found from a cut of up to 4e-3 on either side and not from the tenth of the
// resolution, 0.031: it crept towards two zones 2e-4 short of the contact's and stalled.
// A tension that returns where a cut was made before (within a hundredth of the resolution)
// is cut by its parabola's half-width where that is wider, up to 0.45 of its distance from a
// free end, and a piece beside such a cut is dropped if shorter than the tenth of the scale.
// (Two dips of a zone over two asperities of n = 342, each 4.7e-3 wide below 0 and 9.8e-3
// apart, cut by the tenth, 9.2e-4: Newton's method closed both gaps and the same zone came
// back with the same tensions 400 times; the wave curve m = 20 with n = 4, 342, 240 and 2,
// campaign seed 100, sweep 153 with 16 loads. Cut by their parabolas, the zone is two zones
// with the stretch between them free. Within a tenth of the resolution, a second dip 0.0157
// from a first one cut next to an end passed for it, and the zones cycled: the wave curve
// m = 30.5 with n = 20 and 4, campaign seed 25, sweep 71 with 32 loads, --max-n 32.)
void cut_zones(Configuration& c, const std::vector<Tension>& tensions, double resolution,
               const std::vector<double>& cut_before) {
  const auto returns = [&](double x) {
    return std::any_of(cut_before.begin(), cut_before.end(),
                       [&](double before) { return std::abs(x - before) < returning * resolution; });
  };
  struct Cut {
    double x, margin;  // where, and what is left out on each side
    bool widened;
  };
  for (std::size_t k = c.zones.size(); k-- > 0;) {
    const ZoneUnknowns zone = c.zones[k];
    const double a = zone.geometry.a, b = zone.geometry.b, scale = std::min(b - a, resolution);
    std::vector<Cut> cuts;
    for (const Tension& t : tensions) {
      if (t.zone != k) continue;
      // A dip next to a free end is no parabola (the pressure goes like a root there).
      const double from_ends = std::min(a > 0 ? t.x - a : pi, b < pi ? b - t.x : pi);
      const double below = t.curvature > 0 ? std::sqrt(2 * -t.pressure / t.curvature) : scale;
      const double margin = below < 0.1 * from_ends ? std::min(cut_margin * scale, below) : cut_margin * scale;
      const double wide = std::min(below, 0.45 * from_ends);
      if (returns(t.x) && wide > margin) {
        if (tracing())
          std::fprintf(stderr, "wavecontact trace:   the tension at %.9g returns: cut by %.3g\n", t.x, wide);
        cuts.push_back({t.x, wide, true});
      } else {
        cuts.push_back({t.x, margin, false});
      }
    }
    if (cuts.empty()) continue;
    std::sort(cuts.begin(), cuts.end(), [](const Cut& l, const Cut& r) { return l.x < r.x; });
    c.zones.erase(c.zones.begin() + static_cast<std::ptrdiff_t>(k));
    double lo = a;
    bool after_widened = false;
    cuts.push_back({b, 0.0, false});  // the last piece ends at b
    for (const Cut& cut : cuts) {
      const double hi = std::min(cut.x - cut.margin, b);
      const double shortest = (after_widened || cut.widened ? cut_margin : shortest_piece) * scale;
      if (hi - lo > shortest) {
        const auto share = static_cast<std::size_t>(std::ceil(zone.d.size() * (hi - lo) / (b - a)));
        insert_zone(c, zone_of(lo, hi, std::max<std::size_t>(share, working_nodes)));
      }
      lo = std::max(cut.x + cut.margin, a);
      after_widened = cut.widened;
    }
  }
}

// Whether a tension is a narrow gap's (SettleLimits::narrow_gaps): its width,
// 4 sqrt(-p / p''), below a hundredth of the resolution, its room to the zone's free ends a
// hundred widths, and none marked there before (one that still shows a tension is cut).
bool narrow_gap_tension(const Configuration& c, const Tension& t, double resolution) {
  if (!(t.curvature > 0)) return false;
  const double half = 2 * std::sqrt(-t.pressure / t.curvature);
  const ZoneGeometry& g = c.zones[t.zone].geometry;
  const double room = std::min(g.top() ? pi : t.x - g.a, g.valley() ? pi : g.b - t.x);
  const bool before = std::any_of(c.narrow_gaps.begin(), c.narrow_gaps.end(),
                                  [&](double x) { return std::fabs(x - t.x) < 100 * half; });
  return half <= 0.01 * resolution && room >= 200 * half && !before;
}

// The tensions that are narrow gaps' leave `tensions` and mark them; whether any did.
bool mark_narrow_gaps(Configuration& c, std::vector<Tension>& tensions, double resolution) {
  const auto marked = [&](const Tension& t) {
    if (!narrow_gap_tension(c, t, resolution)) return false;
    if (tracing()) std::fprintf(stderr, "wavecontact trace:   the tension at %.9g is a narrow gap\n", t.x);
    c.narrow_gaps.push_back(t.x);
    return true;
  };
  const std::size_t count = tensions.size();
  tensions.erase(std::remove_if(tensions.begin(), tensions.end(), marked), tensions.end());
  return tensions.size() < count;
}

std::vector<ZoneGeometry> geometries(const Configuration& c) {
  std::vector<ZoneGeometry> g;
  for (const ZoneUnknowns& z : c.zones) g.push_back(z.geometry);
  return g;
}

// The zones `start` for those of c, if they are the same zones (their count, and which reach
// the top or the valley); the nodes stay c's.
void restore_ends(Configuration& c, const std::vector<ZoneGeometry>& start) {
  if (start.size() != c.zones.size()) return;
  for (std::size_t k = 0; k < c.zones.size(); ++k) {
    if (start[k].top() != c.zones[k].geometry.top() || start[k].valley() != c.zones[k].geometry.valley()) return;
  }
  for (std::size_t k = 0; k < c.zones.size(); ++k) c.zones[k].geometry = start[k];
}

}  // namespace

bool window_unresolved(const SurfaceModel& surface, const ZoneUnknowns& z) {
  const std::shared_ptr<const KinkCorrection> window = KinkCorrection::of(surface, z.geometry, z.kink_window);
  return window && window->nodes_within(z.geometry, z.d.size()) < least_window_nodes;
}

bool same_zones(const Configuration& a, const Configuration& b) {
  if (a.zones.size() != b.zones.size()) return false;
  for (std::size_t k = 0; k < a.zones.size(); ++k) {
    if (a.zones[k].geometry.top() != b.zones[k].geometry.top() ||
        a.zones[k].geometry.valley() != b.zones[k].geometry.valley())
      return false;
  }
  return true;
}

Configuration nearby_start(const SurfaceModel& surface, double P, const LoadContact& last, const LoadContact* before) {
  Configuration c = last.contact;
  c.narrow_gaps.clear();  // each load finds its own
  // Two contacts of the same zones and nodes: each end, coefficient and C linear in the load,
  // trusted up to twice the step between them; ends that would leave the half period or
  // cross keep the last contact as it is.
  const auto alike = [&](const Configuration& a, const Configuration& b) {
    if (!same_zones(a, b)) return false;
    for (std::size_t k = 0; k < a.zones.size(); ++k) {
      if (a.zones[k].d.size() != b.zones[k].d.size()) return false;
    }
    return true;
  };
  const double t = before && before->P < last.P ? (P - last.P) / (last.P - before->P) : 0.0;
  if (t > 0 && t <= 2 && alike(before->contact, last.contact)) {
    for (std::size_t k = 0; k < c.zones.size(); ++k) {
      const ZoneUnknowns& b = before->contact.zones[k];
      ZoneUnknowns& z = c.zones[k];
      const double a = z.geometry.top() ? 0.0 : z.geometry.a + t * (z.geometry.a - b.geometry.a);
      const double e = z.geometry.valley() ? pi : z.geometry.b + t * (z.geometry.b - b.geometry.b);
      if (!(a < e && (z.geometry.top() || a > 0) && (z.geometry.valley() || e < pi))) {
        return nearby_start(surface, P, last, nullptr);
      }
      z.geometry = ZoneGeometry(a, e);
      for (std::size_t j = 0; j < z.d.size(); ++j) z.d[j] += t * (z.d[j] - b.d[j]);
    }
    for (std::size_t k = 0; k + 1 < c.zones.size(); ++k) {
      if (!(c.zones[k].geometry.b < c.zones[k + 1].geometry.a)) return nearby_start(surface, P, last, nullptr);
    }
    c.C += t * (last.contact.C - before->contact.C);
  }
  for (ZoneUnknowns& z : c.zones) {
    z.d.resize(std::min(z.d.size(), std::min<std::size_t>(most_working_nodes, width_nodes(z, surface))));
  }
  return c;
}

double coefficient_tail(const std::vector<double>& d) {
  double magnitude = 0;
  for (double v : d) magnitude += std::fabs(v);
  const std::size_t n = d.size();
  return (std::fabs(d[n - 1]) + std::fabs(d[n - 2]) + std::fabs(d[n - 3])) / std::max(magnitude, 1e-300);
}

SettleOutcome settle(const std::shared_ptr<const SurfaceModel>& model, double P, Configuration c, SettleLimits limits,
                     const Checkpoint& checkpoint) {
  const SurfaceModel& surface = *model;
  const ZoneSystem system(surface, P);
  const auto kinked = [&](const ZoneUnknowns& z) {
    return std::any_of(surface.kinks.begin(), surface.kinks.end(),
                       [&](const Kink& k) { return k.angle > z.geometry.a && k.angle < z.geometry.b; });
  };
  // A zone across a kink with under half the nodes its window asks for (width_nodes): a
  // window chosen during Newton's method, as an end crossed the kink, came with the nodes the
  // zone had without it. The wave curve m = 1.04 with n = 16 and 2, continued to P = 2.7275
  // (campaign seed 5, sweep 43 with 64 loads, --max-n 32), converged on 48 nodes with the end
  // 8e-5 past the kink, and the refinement's changes grew from 3.2e-8 to 3.2e-7 at 192: an
  // estimate 32 times the tolerance, where the window's 4096 nodes give 2.8e-10. (Any zone
  // short of them, 4059 of 4096 after a cut, regrew, and its tension at the end came back
  // 400 times: campaign seed 25, sweep 85 with 32 loads, --max-n 32.)
  const auto short_of_its_window = [&](const ZoneUnknowns& z) {
    return kinked(z) && 2 * z.d.size() < std::min<std::size_t>(most_working_nodes, width_nodes(z, surface));
  };
  // The coefficients made consistent with the zones first, for the guess and after every
  // change of zones: Newton's method then starts with the collocation rows met and moves the
  // ends (from one block-Jacobi sweep alone, a zone just cut or merged may start so far off
  // that the damped steps creep).
  const auto consistent = [&](Configuration& z) {
    fit_nodes(z, surface);
    system.relax(z);
    system.choose_windows(z);
    z = system.newton(std::move(z), consistent_residual, checkpoint, true).configuration;
  };
  consistent(c);
  // Where Newton's method started on the present zones, and whether it has since converged on
  // nodes too few for them. A zone across a kink converges like a power of its nodes, and such
  // a contact can sit far from the finer nodes' one (campaign sweep 27 of seed 1 with 12
  // loads: ends 0.035 apart at 64 and 128 nodes), where Newton's method creeps and fails from
  // any count of nodes; from the start's ends it converges in a few steps. A failure after
  // such a growth therefore starts again from those ends, with the grown nodes.
  std::vector<ZoneGeometry> start = geometries(c);
  bool grown_after_converging = false;
  std::vector<double> cut_places;  // where tensions were cut, for cut_zones
  bool met_narrow_gap = false;     // without narrow_gaps, a tension that they would have marked
  const auto fail = [&](std::string why) { return SettleOutcome{std::nullopt, std::move(why), met_narrow_gap}; };
  for (int change = 0; change <= limits.changes; ++change) {
    if (checkpoint) checkpoint(std::numeric_limits<double>::quiet_NaN());
    fit_nodes(c, surface);
    system.choose_windows(c);
    const ZoneSystem::Result r = system.newton(c, working_residual, checkpoint);
    trace_configuration("newton at", P, r.configuration,
                        r.outcome == ZoneSystem::Outcome::converged ? "converged"
                        : r.outcome == ZoneSystem::Outcome::failed  ? "failed"
                                                                    : "a stretch closes");
    c = r.configuration;
    bool zones_changed = false;
    if (r.outcome == ZoneSystem::Outcome::failed) {
      // Zones that came too near for their nodes, or a zone across a kink too coarse for its
      // density, may keep Newton from converging; and a zone across a kink may need finer
      // nodes than its tail shows (its window's edges), up to most_working_nodes.
      if (limits.shortcut || (!fit_nodes(c, surface, true) && !grow_nodes(c, surface, 1e-6, kinked) &&
                              !grow_nodes(c, surface, 0.0, kinked))) {
        char text[120];
        std::snprintf(text, sizeof text, "Newton's method did not converge on %zu zones (residual %.3g)",
                      c.zones.size(), r.residual);
        return fail(text);
      }
      if (grown_after_converging) restore_ends(c, start);
    } else if (r.outcome == ZoneSystem::Outcome::stretch_closes) {
      if (!close_stretch(c, r.stretch)) return fail("every zone vanished");
      zones_changed = true;
    } else if (merge_close_zones(c, surface.resolution)) {
      zones_changed = true;
    } else if (!system.windows_fit(c)) {
      continue;  // a kink window chosen again
    } else if (fit_nodes(c, surface, false, short_of_its_window)) {
      continue;
    } else if (!crowded(c) && grow_nodes(c, surface, working_tail)) {
      grown_after_converging = true;
    } else {
      // A crowded contact is verified before its nodes grow: where it is a root of the coarse
      // equations alone, its nodes would grow to the most for nothing (campaign sweep 1677 of
      // seed 1 from a seed that found its gap of 5.8e-4: converged on 24 nodes with that gap
      // at 1e-5, then 29 s of growth and creeping before the tension that cut it was found).
      // Nor is it left to the refinement's verification alone when the start came from the
      // loads before: the bench's map of 10^4 points then took 6.2 s instead of 3.8 (each
      // contact the refinement refuses settles again with all its changes).
      const Verification v =
          verify(ContactSolution(model, c), gap_tolerance * surface.height_range, pressure_tolerance);
      if (tracing()) {
        std::fprintf(stderr,
                     "wavecontact trace: verified: %zu tension%s, %zu penetration%s (lowest gap %.3g at %.6g)\n",
                     v.tensions.size(), v.tensions.size() == 1 ? "" : "s", v.penetrations.size(),
                     v.penetrations.size() == 1 ? "" : "s", v.lowest_gap, v.x_of_lowest_gap);
        for (const Tension& t : v.tensions) {
          std::fprintf(stderr, "wavecontact trace:   tension %.3g at %.9g in zone %zu (curvature %.3g)\n", t.pressure,
                       t.x, t.zone, t.curvature);
        }
        for (const Penetration& p : v.penetrations) {
          std::fprintf(stderr, "wavecontact trace:   penetration %.3g at %.9g in [%.9g, %.9g] (curvature %.3g)\n",
                       p.depth, p.x, p.lo, p.hi, p.curvature);
        }
      }
      if (v.tensions.empty() && v.penetrations.empty()) {
        if (!grow_nodes(c, surface, working_tail)) return {std::move(c), {}, met_narrow_gap};
        grown_after_converging = true;
      } else if (grow_unresolved_windows(c, surface, v.tensions)) {
        grown_after_converging = true;
      } else {
        std::vector<Tension> cut = v.tensions;
        if (limits.narrow_gaps) {
          if (mark_narrow_gaps(c, cut, surface.resolution) && cut.empty() && v.penetrations.empty())
            continue;  // verified again with its narrow gaps
        } else if (!met_narrow_gap) {
          met_narrow_gap = std::any_of(cut.begin(), cut.end(),
                                       [&](const Tension& t) { return narrow_gap_tension(c, t, surface.resolution); });
        }
        cut_zones(c, cut, surface.resolution, cut_places);
        for (const Tension& t : cut) cut_places.push_back(t.x);
        if (cut.empty()) open_zones(c, v.penetrations, surface.resolution);
        if (c.zones.empty()) return fail("every zone was cut away");
        zones_changed = true;
      }
    }
    consistent(c);
    if (zones_changed) start = geometries(c), grown_after_converging = false;
  }
  return fail("the zones still changed after " + std::to_string(limits.changes) + " changes");
}

}  // namespace wavecontact::detail
