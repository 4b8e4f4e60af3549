// Eq. 12 for a right-hand side g of eq. 5 that is piecewise analytic with a kink in its slope at
// v = +-beta: a profile built with |.| (eq. 2 beyond a = b1/2, or a user profile with abs())
// whose contact zone reaches beyond the change of branch. The pressure comes from the emitted
// closed forms' parts (derive/beyond_branch.hpp, derive/emit_common.hpp); this chooses them.
#pragma once

#include <functional>

namespace wavecontact::detail {

// The parts of the closed-form pressure at a point on one branch ("own"), as emitted per side:
// the own piece's moment, the other piece's with its Cauchy factor, or without it plus the
// jump's term, in I_{j,l} or the edge basis.
enum class BranchPart { own, own_edge, other_cauchy, other_cauchy_edge, other, other_edge, jump };

// p(x) from its parts: each piece in the basis its pole factor's argument asks for (the edge
// basis where it is < 0: the pole just beyond the piece's end at the branch point), and the
// other piece with its Cauchy factor where |g_other(u)/g_own(u)| = |other_over_own| > 2 (near
// the other branch's pole, where the jump's term would cancel against the rest), else with the
// jump apart (up to the branch point, where the Cauchy factor's logarithm would). At the branch
// point itself (at_branch) the jump's term is its limit, 0 (the jump vanishes like s - beta^2,
// the Cauchy moment grows like log|s - beta^2|).
double beyond_branch_pressure(const std::function<double(BranchPart)>& part, double own_argument,
                              double other_argument, double other_over_own, bool at_branch);

}  // namespace wavecontact::detail
