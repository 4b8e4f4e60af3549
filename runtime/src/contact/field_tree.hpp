// The potential of many zones at many points in O(log zones) a point (docs/contact.md): a
// tree code. The zones, in order along s = cos x^, are the leaves of a balanced binary tree;
// each node holds the multipole moments of its zones' densities about its centre,
//   Psi(s) = -(1/pi) [mu_0 log|s - c| - sum_{k>=1} mu_k / (k (s - c)^k)],
//   mu_k = Int q(t) (t - c)^k dt,
// which converge geometrically once |s - c| exceeds the node's radius; a point takes a node's
// moments when the node is far enough (radius/distance <= 0.4, about 43 terms for 1e-17) and
// opens it otherwise; a leaf's zones act by their closed forms (zone_field.hpp). Distances in
// s are formed from 1 - s = 2 sin^2(x^/2) near the top and 1 + s = 2 cos^2(x^/2) near the
// valley, so that zones crowded at either end keep their digits.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "configuration.hpp"
#include "zone_field.hpp"

namespace wavecontact::detail {

// A point of [-1, 1] in s with its distances from both ends, each to full relative precision.
struct Abscissa {
  double s = 0, from_top = 0, from_valley = 0;  // s, 1 - s, 1 + s
  static Abscissa of_angle(const HalfAngle& x);
  static Abscissa midpoint(const Abscissa& a, const Abscissa& b);
};
// a - b in s.
double difference(const Abscissa& a, const Abscissa& b);

class FieldTree {
 public:
  // The smooth densities (coefficients d) of the configuration's zones; a kink correction is
  // not in it (the few zones that have one add its potential themselves). The tree refers to
  // c's zones, which must outlive it.
  explicit FieldTree(const Configuration& c);

  // The potential of every zone but `skip` (any value past the last zone skips none) at a
  // batch of nearby points x[i] (one zone's nodes), as its values at a reference point x_ref
  // of the batch and the differences from it: the differences keep their digits where the
  // potential itself is large (the sum over every zone) and its variation over the batch is
  // small. A node acts on the whole batch by its moments when it is far enough from the
  // nearest point. The points must lie off every zone they count.
  struct Batch {
    double at_reference = 0;
    std::vector<double> difference;  // Psi(x_i) - Psi(x_ref)
    std::vector<double> slope;       // dPsi/ds at x_i, when asked for
  };
  // `offsets`, if not null, are s_i - s_ref to their own precision (a zone's nodes, placed in
  // s: node_offsets), which the moments take; else they are taken from the angles. A zone
  // that acts directly takes the angles.
  Batch evaluate(std::size_t skip, const std::vector<double>& x, double x_ref, bool slopes,
                 const double* offsets = nullptr) const;

 private:
  static constexpr int order = 44;  // moments mu_0 .. mu_{order-1}
  struct Node {
    std::size_t first = 0, last = 0;   // zones [first, last)
    std::size_t children[2] = {0, 0};  // 0: a leaf
    Abscissa centre;
    double radius = 0;
    // Computed when a point first takes them (with_moments): most nodes never act by them,
    // the root spanning every zone among them.
    mutable std::vector<double> moments;         // mu_k / radius^k
    mutable std::vector<double> moments_over_k;  // the same over k (k >= 1)
  };
  std::size_t build(std::size_t first, std::size_t last);
  // Node `at`, its moments computed once (by whichever thread asks first).
  const Node& with_moments(std::size_t at) const;
  void compute_moments(const Node& node) const;

  const std::vector<ZoneUnknowns>& zones_;
  std::vector<Abscissa> upper_, lower_;  // each zone's ends in s: at x^ = a and at x^ = b
  std::vector<Node> nodes_;
  std::unique_ptr<std::once_flag[]> moments_computed_;  // one a node
};

}  // namespace wavecontact::detail
