#include "kinked_inversion.hpp"

#include <cmath>

namespace wavecontact::detail {

double beyond_branch_pressure(const std::function<double(BranchPart)>& part, double own_argument,
                              double other_argument, double other_over_own, bool at_branch) {
  const bool other_edge = other_argument < 0;
  const double own = part(own_argument < 0 ? BranchPart::own_edge : BranchPart::own);
  if (std::fabs(other_over_own) > 2) {
    return own + part(other_edge ? BranchPart::other_cauchy_edge : BranchPart::other_cauchy);
  }
  const double other = part(other_edge ? BranchPart::other_edge : BranchPart::other);
  return at_branch ? own + other : own + other + part(BranchPart::jump);
}

}  // namespace wavecontact::detail
