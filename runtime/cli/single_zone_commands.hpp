// pressure --a, load, curve and solve --single-zone: one zone of half-width a, in closed form,
// refused where it is not the contact.
#pragma once

#include <string>
#include <vector>

#include "options.hpp"
#include "wavecontact/stability.hpp"
#include "wavecontact/two_scale.hpp"

namespace wavecontact::cli {

// The zone for a: refuses it if the total pressure goes negative in it (naming x and p) or
// the surface penetrates off it (naming x and the penetration).
TwoScaleContact admissible_contact(const TwoScaleParams& params, double a, Form form);

// The pressure at the points xs: total, waviness, roughness.
std::string pressure_table(const TwoScaleParams& p, double a, const std::vector<double>& xs, Form form);

// The load, mean pressure and contact fraction of the zone.
std::string load_row(const TwoScaleParams& p, double a, Form form);

// pa/p* against 2a/L1 and p(0) against a, over points half-widths up to b1/2.
std::string curve_table(const TwoScaleParams& p, int points);

// solve --single-zone: every half-width carrying the load.
std::string single_zone_rows(const ProfileOptions& profile, const ZoneOptions& zone);

}  // namespace wavecontact::cli
