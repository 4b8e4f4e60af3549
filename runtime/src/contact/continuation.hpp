// The unique contact of an even periodic surface under a load (the minimiser of a strictly
// convex energy), by continuation in the load (docs/contact.md).
//
// The contact set grows with the load (the obstacle problem's comparison principle), so from
// a small zone at the highest point the events are: a gap reaching 0 off the zones (new
// zones, every one a step meets at once), a gap between zones closing (they merge), a zone
// reaching the top or the valley, and full contact, whose onset is known beforehand (p =
// P/(2 pi) + p0 in full contact). Each step's configuration solves the zone system
// (zone_system.hpp) and is verified on the whole half period (verification.hpp); the last
// is polished: the zones' Chebyshev nodes grow until their coefficients' tails meet the
// tolerance, and the error is estimated against a solve on more nodes.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "work_budget.hpp"
#include "solution.hpp"
#include "surface_model.hpp"

namespace wavecontact::detail {

struct SolvedContact {
  std::shared_ptr<const ContactSolution> solution;
  double P = 0;
  double error_estimate = 0;  // relative: the pressure to its maximum, the ends to the period
  double rounding = 0;        // the part of it that rounding alone makes
  int nodes = 0;              // the most Chebyshev nodes of a zone
};

class ContactSolver {
 public:
  // tolerance: the relative error estimate the result must meet; nodes > 0 fixes the nodes
  // per zone (the estimate is then against nodes + 4).
  ContactSolver(std::shared_ptr<const SurfaceModel> surface, double tolerance, int nodes, WorkBudget budget);

  // The load (normalised) from which the contact is full.
  double full_contact_load() const;

  // The contact at each load (any order), by one continuation through them.
  std::vector<SolvedContact> solve(const std::vector<double>& loads) const;

 private:
  struct State {
    Configuration c;
    double P;
  };
  std::optional<State> settle(Configuration c, double P) const;
  std::optional<State> advance(const State& from, const State* before, double P) const;
  State seed(double P) const;
  std::optional<State> single_zone(double P) const;
  SolvedContact full_contact(double P) const;
  SolvedContact polish(const State& state) const;
  Configuration full_contact_configuration(double P, int nodes) const;
  void check_budget() const;

  std::shared_ptr<const SurfaceModel> surface_;
  double tolerance_;
  int fixed_nodes_;
  WorkBudget budget_;
  double top_angle_ = 0, top_curvature_ = 0, height_range_ = 0;
  double onset_ = 0;
  mutable double reached_load_ = 0, target_load_ = 0;
  mutable std::size_t reached_zones_ = 0;
};

// Whether the single zone [0, a^] carrying its own load (bounded at a^) is the contact.
struct SingleZoneResult {
  bool solution, penetrates;
  double lowest_gap, x_of_lowest_gap;
  double lowest_pressure, x_of_lowest_pressure;
};
SingleZoneResult check_single_zone(const std::shared_ptr<const SurfaceModel>& surface, double a);

}  // namespace wavecontact::detail
