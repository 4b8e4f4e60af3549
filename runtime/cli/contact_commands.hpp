// solve, contact and pressure --P: the real contact at a load (wavecontact/contact.hpp), for
// the wave curve with roughness harmonics or a user profile.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "wavecontact/contact.hpp"

namespace wavecontact::cli {

// One row per load: the zones, the contact fraction, p(0), the largest pressure and the
// error estimate. pstar_load = pi E* H1 (P at pa/p* = 1) where the surface has an H1.
std::string contact_rows(const Surface& surface, const std::vector<double>& loads, std::optional<double> pstar_load,
                         const SolverOptions& options);

// One row per zone of the period [-b1, b1): its ends, the load it carries, its largest
// pressure and where.
std::string contact_zones(const Surface& surface, double P, const SolverOptions& options);

// The pressure and the gap of the contact at the points xs.
std::string contact_pressure(const Surface& surface, double P, const std::vector<double>& xs,
                             const SolverOptions& options);

}  // namespace wavecontact::cli
