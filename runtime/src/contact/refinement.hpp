// The last stage of a solve (docs/contact.md): the settled contact's zones get Chebyshev
// nodes until their series converge, and the error is estimated by comparing solves on more
// nodes; the rounding of the sums that make each zone's equations is estimated apart.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "configuration.hpp"
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

// A refined contact, or, where its finer nodes show a tension or a penetration the settled
// contact's did not, the refined configuration to settle again and why it was refused.
struct Refinement {
  std::optional<SolvedContact> solved;
  Configuration refused;
  std::string refusal;
};

// tolerance: the relative error estimate the result must meet; fixed_nodes > 0 fixes the
// nodes per zone (the estimate is then against half as many again). Throws BeyondReach if
// Newton's method fails on more nodes.
Refinement refine(const std::shared_ptr<const SurfaceModel>& surface, const Configuration& settled, double P,
                  double tolerance, int fixed_nodes, const Checkpoint& checkpoint);

}  // namespace wavecontact::detail
