// The unique contact of an even periodic surface under a load (the minimiser of a strictly
// convex energy), at each of several loads (docs/contact.md).
//
// At each load, in increasing order: from the contacts at the previous loads extrapolated to
// this one (nearby_start) while the steps are small and the zones follow them, or at the
// first load (or if that fails) one zone at the top when it is the contact, else the zones
// of the contact on a uniform grid (grid_seed.hpp), then a grid twice as fine: made exact
// by Newton's method on the zone system with every change of zones it or the verification
// calls for (active_set.hpp). The result is refined
// (refinement.hpp): nodes until the series converge, an error estimate, the rounding. Full
// contact's onset is known beforehand (p = P/(2 pi) + p0 in full contact).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "active_set.hpp"
#include "configuration.hpp"
#include "refinement.hpp"
#include "surface_model.hpp"
#include "support/work_budget.hpp"

namespace wavecontact::detail {

class ContactSolver {
 public:
  // tolerance: the relative error estimate the result must meet; nodes > 0 fixes the nodes
  // per zone.
  ContactSolver(std::shared_ptr<const SurfaceModel> surface, double tolerance, int nodes, WorkBudget budget);

  // The load (normalised) from which the contact is full.
  double full_contact_load() const;

  // The contact at each load (any order).
  std::vector<SolvedContact> solve(const std::vector<double>& loads) const;

 private:
  LoadContact settle_at(double P, const LoadContact* previous, const LoadContact* before) const;
  std::optional<Configuration> single_zone(double P) const;
  SolvedContact full_contact(double P) const;
  Configuration full_contact_configuration(double P, int nodes) const;
  // The budget's check at a safe point; residual: Newton's there (NaN elsewhere).
  void check_budget(double residual) const;

  std::shared_ptr<const SurfaceModel> surface_;
  double tolerance_;
  int fixed_nodes_;
  WorkBudget budget_;
  double onset_ = 0;
  mutable double target_load_ = 0;
  mutable std::size_t zones_tried_ = 0;
  mutable double lowest_residual_ = 0;  // of Newton's method on this load (infinite: none yet)
};

// Whether the single zone [0, a^] carrying its own load (bounded at a^) is the contact.
struct SingleZoneResult {
  bool solution, penetrates;
  double lowest_gap, x_of_lowest_gap;
  double lowest_pressure, x_of_lowest_pressure;
};
SingleZoneResult check_single_zone(const std::shared_ptr<const SurfaceModel>& surface, double a);

}  // namespace wavecontact::detail
