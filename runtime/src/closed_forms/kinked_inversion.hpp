// Eq. 12 for a right-hand side g of eq. 5 that is piecewise analytic with a kink in its slope at
// v = +-beta: a profile built with |.| (eq. 2 beyond a = b1/2, or a user profile with abs())
// whose contact zone reaches beyond the change of branch. The pressure comes from the emitted
// closed forms' parts (derive/formulas/beyond_branch.hpp, derive/emit/shared_pieces.hpp); this chooses them and
// keeps the atoms of the zone once per zone.
#pragma once

#include <array>
#include <functional>
#include <limits>

#include "closed_forms/cauchy_atom_table.hpp"
#include "wavecontact/angles.hpp"

namespace wavecontact::detail {

// The parts of the closed-form pressure at a point on one branch ("own"), as emitted per side:
// the own piece's moment, the other piece's with its Cauchy factor, or without it plus the
// jump's term, in I_{j,l} or the edge basis.
enum class BranchPart { own, own_edge, other_cauchy, other_cauchy_edge, other, other_edge, jump };

// The emitted forms of one side of the branch point, the zone (parameters, Ca, Sa) bound.
struct BranchSideForms {
  int atom_counts[7];
  // y and 1 + y of the Cauchy factor at the point.
  std::function<void(const PointAngles&, double* y)> cauchy_argument;
  // A part's atoms, at the point's y and 1 + y (the zone's parts do not use them).
  std::function<void(BranchPart, double y, double one_plus_y, double* atoms)> atoms;
  std::function<double(BranchPart, const PointAngles&, const double* atoms)> part;
};

// One side of the branch point of one zone. Each piece is taken in the basis its pole factor's
// argument asks for (the edge basis where it is < 0: the pole just beyond the piece's end at the
// branch point); the atoms of the own piece and of the other piece without its Cauchy factor
// are the zone's, computed here once.
class BranchSide {
 public:
  BranchSide(BranchSideForms forms, double own_argument, double other_argument);

  // p at a point of the side: the other piece with its Cauchy factor where
  // |g_other(u)/g_own(u)| = |other_over_own| > 2 (near the other branch's pole, where the jump's
  // term would cancel against the rest), else with the jump apart (up to the branch point, where
  // the Cauchy factor's logarithm would). At the branch point itself (at_branch) the jump's term
  // is its limit, 0 (the jump vanishes like s - beta^2, the Cauchy moment grows like
  // log|s - beta^2|).
  // The Cauchy part's atoms come from `table` (cauchy_table()) where one of its panels serves
  // the point, built first if `build`, else directly; eta is the point's cauchy_eta where known
  // already.
  double pressure(const PointAngles& point, double other_over_own, bool at_branch,
                  double eta = std::numeric_limits<double>::quiet_NaN(), const CauchyAtomTable* table = nullptr,
                  bool build = false) const;

  // eta = log(1 + y) of a point where pressure() takes the Cauchy factor, NaN elsewhere.
  double cauchy_eta(const PointAngles& point, double other_over_own) const;
  // A table, empty yet, of that part's atoms.
  CauchyAtomTable cauchy_table() const;

 private:
  using Atoms = std::array<double, max_branch_atoms>;
  double part_at_point(BranchPart part, const PointAngles& point) const;
  // The other piece with its Cauchy factor (see pressure()).
  double cauchy_part(const PointAngles& point, double eta, const CauchyAtomTable* table, bool build) const;
  double eta_at(const PointAngles& point) const;

  BranchSideForms forms_;
  BranchPart own_, other_, other_cauchy_;
  Atoms own_atoms_{}, other_atoms_{};
};

}  // namespace wavecontact::detail
