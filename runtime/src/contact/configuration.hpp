// The unknowns of a contact: its zones in the half period, each with its density's
// Chebyshev coefficients, and the constant C of the rigid approach (docs/contact.md).
#pragma once

#include <vector>

#include "zone.hpp"

namespace wavecontact::detail {

struct ZoneUnknowns {
  ZoneGeometry geometry;
  std::vector<double> d;  // the density's coefficients, one a Chebyshev node
  // The radius in s of the window of the kink correction (kink_correction.hpp) the density
  // holds beside d: 0 for none. Kept through a Newton solve, so that its equations are smooth.
  double kink_window = 0;
};

struct Configuration {
  std::vector<ZoneUnknowns> zones;  // in increasing x^, disjoint
  double C = 0;
  // Where a zone holds a narrow gap (narrow_gap.hpp): near each, its pressure's negative
  // minimum is the gap's (x^). Carried through Newton's method; one outside every zone is idle.
  std::vector<double> narrow_gaps;
};

}  // namespace wavecontact::detail
