// The contact at one load from a guess of its zones (docs/contact.md): Newton's method on
// the zone system, then every change of the zones that it or the verification of the whole
// half period calls for, until the configuration is a contact:
//   - a stretch that Newton's method closes: a gap between zones (they merge), a zone (it
//     vanishes), the stretch to the top or to the valley (the zone runs through it);
//   - a gap below 0 off the zones: a new zone at each penetration;
//   - a pressure below 0 on a zone: the zone is cut there (split, or shortened at its end,
//     or let go of the top or the valley).
// The frictionless contact under a load is unique, so whatever the guess, a configuration
// that passes the verification is the contact.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "configuration.hpp"
#include "surface_model.hpp"
#include "zone_system.hpp"

namespace wavecontact::detail {

inline constexpr int working_nodes = 16;           // Chebyshev nodes of a zone while settling
inline constexpr double working_residual = 1e-10;  // Newton's tolerance while settling
// With the ends held, for a start whose collocation rows are met: the ends then move, and
// every row with them (finer costs iterations; at 1e-4 the rounding reached by the solves
// that follow differs, up to 1e-11 on 35 zones).
inline constexpr double consistent_residual = 1e-8;
inline constexpr double gap_tolerance = 1e-9;       // of the height range
inline constexpr double pressure_tolerance = 1e-9;  // of the largest pressure
// A zone's nodes at most, once refined (and full contact's). The roughness H cos(n x^) is a
// polynomial of degree n in s = cos x^, which a zone over most of the period needs nearly all
// of: a zone at the cap is estimated against half as many, and up to n = max_roughness_n =
// 4096 half of 16384 still resolves it (with a cap of 4096, wide zones at n above about 2048
// were estimated against 2048 nodes, 3e-3 to 7e-2 for contacts right within 1e-11).
inline constexpr int most_nodes = 16384;
// A zone across a kink: its window may be as narrow as the sliver between the kink and an end
// (kink_correction.hpp), and Chebyshev nodes resolve it only where they crowd towards that end.
inline constexpr int most_kinked_nodes = 32768;
inline constexpr int most_working_nodes = 4096;  // while settling, the zones are what matters

// The nodes a kink window needs for its own shape: fewer, a zone's series wiggles where the
// window meets the nodes crowding towards a near end (settle), and its changes as the nodes
// double need not fall yet (refine).
inline constexpr double least_window_nodes = 32;
// Whether a zone's kink window holds fewer than least_window_nodes of its nodes (false for a
// zone without a window).
bool window_unresolved(const SurfaceModel& surface, const ZoneUnknowns& z);

// A guess for settle at the load P from the contacts at the last loads of a sweep: with the
// contact before it of the same zones and nodes, each end, coefficient and C extrapolated
// linearly in the load (up to twice the step between the two), else the last contact; each
// zone's series then cut to the nodes its width asks for (those that near neighbours or a
// kink's window asked for at that load are asked for again where still needed).
struct LoadContact {
  double P = 0;
  Configuration contact;
  bool continued = false;       // settled from such a guess at the loads before it
  bool met_narrow_gap = false;  // its settling met a tension that narrow gaps would hold
};
Configuration nearby_start(const SurfaceModel& surface, double P, const LoadContact& last, const LoadContact* before);

// Whether two contacts have the same zones: as many, the same ones through the top and the valley.
bool same_zones(const Configuration& a, const Configuration& b);

// The part of a zone's coefficients the last three hold: how far its series is from converged.
double coefficient_tail(const std::vector<double>& d);

struct SettleOutcome {
  std::optional<Configuration> contact;
  std::string failure;          // why not, when there is none
  bool met_narrow_gap = false;  // a tension on the way that SettleLimits::narrow_gaps would mark
};

// How far settle goes: at most `changes` changes of zones. A shortcut, a guess with a surer
// start behind it, is given up at Newton's method's first failure instead of mended by more
// nodes: on a dense multi-scale sweep (campaign seed 11, sweep 82 with 60 loads) a failing
// start from the previous load's contact grew nodes for 10 s at one load, nearly as long as
// the whole sweep takes from the grid's seed at every load (11.3 s).
// With narrow_gaps, a tension whose inner solution is a gap far narrower than the resolution
// and than its room in the zone becomes a narrow gap of it (narrow_gap.hpp) instead of a cut;
// the solver asks for that only where settling without has failed.
struct SettleLimits {
  int changes = 0;
  bool shortcut = false;
  bool narrow_gaps = false;
};

// The contact under the load P from `guess` (its coefficients need not solve anything),
// within `limits`; `checkpoint` is called between Newton steps (the work budget).
SettleOutcome settle(const std::shared_ptr<const SurfaceModel>& surface, double P, Configuration guess,
                     SettleLimits limits, const Checkpoint& checkpoint);

}  // namespace wavecontact::detail
