// The unknowns of a contact: its zones in the half period, each with its density's
// Chebyshev coefficients, and the constant C of the rigid approach (docs/contact.md).
#pragma once

#include <vector>

#include "zone.hpp"

namespace wavecontact::detail {

struct ZoneUnknowns {
  ZoneGeometry geometry;
  std::vector<double> d;  // N + 1 coefficients (the zone's nodes: N + 1)
  double birth_load = -1;  // where the continuation saw it open (negative: not known)
};

struct Configuration {
  std::vector<ZoneUnknowns> zones;  // in increasing x^, disjoint
  double C = 0;
};

}  // namespace wavecontact::detail
