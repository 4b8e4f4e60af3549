// Whether a contact is a solution on the whole half period: p >= 0 on every zone and
// gap >= 0 everywhere off them, the top and the valley included (docs/contact.md). The gap
// is sampled eight times a shortest wavelength and every local minimum that may fall below 0
// refined (local_minima); the pressure likewise on each zone.
#pragma once

#include <functional>
#include <limits>
#include <vector>

#include "solution.hpp"

namespace wavecontact::detail {

struct Penetration {
  double x;          // the deepest point (x^)
  double depth;      // the gap there (< 0)
  double curvature;  // d^2 gap / dx^2 there
  double lo, hi;     // the gap region it lies in
};

struct Tension {
  std::size_t zone;  // where the pressure has a negative local minimum
  double x, pressure;
  double curvature;  // d^2 p / dx^2 there (0 if not positive, or too near an end to tell)
};

struct Verification {
  double highest_pressure = 0, x_of_highest_pressure = 0;
  double lowest_pressure = 0, x_of_lowest_pressure = 0;  // over the zones
  double lowest_gap = 0, x_of_lowest_gap = 0;            // off them
  std::vector<Penetration> penetrations;                 // gap below -gap_tolerance
  std::vector<Tension> tensions;                         // p below -pressure_tolerance * highest
  bool pressure_ok = true;                               // lowest >= -pressure_tolerance * highest
};

Verification verify(const ContactSolution& solution, double gap_tolerance, double pressure_tolerance);

// The highest pressure at verify()'s samples of the zones (the gap left unchecked).
double highest_sampled_pressure(const ContactSolution& solution);

// A function evaluated at many points at once: f(x, values, count).
using BatchFunction = std::function<void(const double*, double*, std::size_t)>;

// The local minima of f over the samples (x sorted): (x, f(x)) pairs; only those that may lie
// at or below `at_most`. The lowest sample of a parabola misses its bottom by at most a
// quarter of its rise to the higher neighbour at even spacing, by less than that rise while
// neighbouring spacings differ less than 4.8-fold: a well sampled higher than at_most by that
// rise is left out. A minimum between two samples is refined by Brent's method between its
// neighbours. A minimum at the first or last sample is probed towards that end in one batch,
// at up to end_probes points each half as far from it as the one before, none closer than
// `closest` (the gap: 0; a zone's pressure: its nearest node's distance from the end); only
// a probe below the end starts Brent's method, between the probes beside it.
std::vector<std::pair<double, double>> local_minima(const std::vector<double>& xs, const std::vector<double>& values,
                                                    const BatchFunction& f,
                                                    double at_most = std::numeric_limits<double>::infinity(),
                                                    double closest = 0);
inline constexpr int end_probes = 24;

}  // namespace wavecontact::detail
