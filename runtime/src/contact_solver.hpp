// The unique contact of an even periodic surface under a load (the minimiser of a strictly
// convex energy): the zones of the half period [0, pi] (normalised x^) and their pressure.
//
// For a given set of zones, the ends solve the conditions of IntervalInversion (boundedness
// at every end, the load, the closure of every gap: one rigid approach) by Newton's method.
// The set of zones comes from continuation in the load from a small zone at the highest
// point of the surface. The contact set grows with the load (the obstacle problem's
// comparison principle), so the events are: the gap reaching 0 off the zones (a zone opens
// there: the load of the event is located by the secant method on the lowest gap, and the
// new zone starts small just past it), a gap between zones closing (they merge; where the
// steps approach the closing without reaching it, beyond it by the secant method on the
// merged zone's lowest pressure), a zone reaching the top or the valley, and full contact,
// whose onset load is known in closed form (p = P/(2 pi) + p0 in full contact). Every
// accepted state is checked: p >= 0 on the zones and gap >= 0 off them (a shallow penetration
// only if the polishing order confirms it). Any admissible state is the contact at its load (the
// solution is unique): where one zone at the top is admissible no continuation is needed.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "interval_inversion.hpp"
#include "work_budget.hpp"

namespace wavecontact::detail {

struct SolvedContact {
  std::vector<Zone> zones;
  double P;
  int order;              // Gauss-Legendre points per panel of the final solution
  double error_estimate;  // relative: pressure to its maximum, ends to the period
  std::shared_ptr<const IntervalInversion> inversion;  // prepared
};

class ContactSolver {
 public:
  // tolerance: the relative error estimate the result must meet; order > 0 fixes the
  // quadrature order instead (the estimate is then against order + 2).
  ContactSolver(SurfaceSlope surface, double tolerance, int order = 0, WorkBudget budget = {1e300, {}});

  // The load (normalised) from which the contact is full, at the polishing order (computed
  // on first use).
  double full_contact_load() const;

  // The contact at each load (any order), by one continuation through them.
  std::vector<SolvedContact> solve(const std::vector<double>& loads) const;

 private:
  // An admissible contact on the way: zones, load, the Jacobian of its ends' conditions,
  // and its evaluators (for the gap where the next zone opens).
  struct State {
    std::vector<Zone> zones;
    double P;
    Eigen::MatrixXd jacobian;
    std::shared_ptr<const IntervalInversion> inversion;
  };
  enum class Outcome { converged, merge, top, valley, failed };
  struct NewtonResult {
    Outcome outcome;
    std::vector<Zone> zones;
    std::size_t index = 0;  // the gap (between zones index and index + 1) for merge
  };
  // Newton's method on the free ends, from `zones`, until every residual is below
  // tolerance; jacobian: in, a Jacobian to start from (same size) or empty; out, the last one.
  NewtonResult newton(std::vector<Zone> zones, double P, int order, double tolerance,
                      Eigen::MatrixXd& jacobian) const;
  // Newton's method through the topology events it meets (merge, top, valley).
  std::optional<State> settle(std::vector<Zone> zones, double P, Eigen::MatrixXd jacobian) const;
  // p >= 0 on the zones, gap >= 0 off them; the penetrated stretches otherwise, each as the
  // zone to start from (around its deepest point) and its depth.
  struct Penetration {
    Zone zone;
    double x, depth;  // deepest point (x^) and gap there (< 0)
    double curvature;  // of the gap there, d2 gap/dx^2 > 0
  };
  struct Check {
    bool pressure_ok;
    std::vector<Penetration> penetrations;
  };
  Check check(const IntervalInversion& inversion) const;
  std::optional<State> single_zone(double P) const;
  State seed(double P) const;
  // One step of the continuation from an admissible state to the load P: a state at P, or at
  // a load in between (the load of an event), or nothing (the step was too long).
  std::optional<State> advance(const State& from, double P, const State* before) const;
  // Past the merge of two zones whose gap closes between `before` and `from` (same zones):
  // the merged contact at a load in (from.P, limit], or nothing.
  std::optional<State> merge_ahead(const State& from, const State& before, double limit) const;
  SolvedContact refine(const State& state) const;

  // The budget's check, naming how far the solve got.
  void check_budget() const;

  SurfaceSlope surface_;
  double tolerance_;
  WorkBudget budget_;
  mutable double reached_load_ = 0, target_load_ = 0;  // of the continuation (normalised)
  mutable std::size_t reached_zones_ = 0;
  int fixed_order_;
  double height_range_;       // max y - min y: the gap scale
  double top_angle_;          // x^ of the highest point
  double onset_estimate_;                // full contact's onset at the continuation order
  mutable std::optional<double> onset_;  // and polished
};

// Whether the single zone [0, a^] (a^ in (0, pi)) carrying its own load is the contact:
// p >= 0 on it and gap >= 0 off it (beyond -1e-9 of the height range); the lowest gap and
// pressure, and where (x^, normalised p^).
struct SingleZoneResult {
  bool solution, penetrates;
  double lowest_gap, x_of_lowest_gap;
  double lowest_pressure, x_of_lowest_pressure;
};
SingleZoneResult check_single_zone(const SurfaceSlope& surface, double a);

}  // namespace wavecontact::detail
