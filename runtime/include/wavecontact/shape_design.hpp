// Shape design (the seed's conclusion: the asperity shape can be chosen to make the contact
// pressure uniform): for a given load, the shape parameter m of the wave curve whose contact
// pressure is most uniform, i.e. that minimises max p / mean p over the contact zone.
//
// max p / mean p depends on m and pa/p* only (H1, b1 and E* scale out). The zone is the
// stable, admissible single zone that carries the load (stability.hpp); where the load has
// no such zone (beyond the largest single-zone load) the shape is infeasible.
#pragma once

namespace wavecontact {

struct PressureUniformity {
  double m;                // shape parameter
  double a_over_b1;        // contact half-width / b1
  double max_over_mean;    // max_{|x|<a} p(x) / (P / 2a), >= 1
  double x_of_max_over_a;  // where the maximum is, x/a in [0, 1)
};

// max p / mean p for shape m >= 0 at pa/p* = ratio > 0. Throws std::domain_error if no
// stable, admissible single zone carries that load. The maximum is located on 256 points
// and refined by Brent's method.
PressureUniformity pressure_uniformity(double m, double ratio);

// The m in [0, m_max] minimising max p / mean p at pa/p* = ratio: Brent's method
// (Boost.Math brent_find_minima) in log(1 + m), started from the best of 24 shapes spaced
// evenly in log(1 + m) so that it settles in the global minimum. Infeasible shapes count as
// +infinity; throws std::domain_error if every shape is.
PressureUniformity most_uniform_shape(double ratio, double m_max = 100);

}  // namespace wavecontact
