// pressure --a, load, solve --single-zone and curve for a user profile (--profile-name,
// wavecontact/profile.hpp); the contact at a load is contact_commands.hpp's.
#pragma once

#include <string>
#include <vector>

#include "wavecontact/profile.hpp"
#include "wavecontact/stability.hpp"

namespace wavecontact::cli {

// The profile `name` with the parameters "NAME=VALUE" (UsageError if one is malformed).
Profile user_profile(const std::string& name, const std::vector<std::string>& parameters, double b1, double E);

// CSV bodies with their header lines of one zone (--a) or the single-zone family
// (solve --single-zone); InadmissibleError if p < 0 in the zone or the gap < 0 off it.
std::string user_profile_pressure(const Profile& profile, double a, const std::vector<double>& xs);
std::string user_profile_load(const Profile& profile, double a);
std::string user_profile_solve(const Profile& profile, double P);
std::string user_profile_curve(const Profile& profile, int points);

}  // namespace wavecontact::cli
