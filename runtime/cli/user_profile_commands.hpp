// pressure, load, solve and curve for a user profile (--profile-name, wavecontact/profile.hpp).
#pragma once

#include <string>
#include <vector>

#include "wavecontact/profile.hpp"
#include "wavecontact/stability.hpp"

namespace wavecontact::cli {

// The profile `name` with the parameters "NAME=VALUE" (UsageError if one is malformed).
Profile user_profile(const std::string& name, const std::vector<std::string>& parameters,
                     double b1, double E);

// Every half-width carrying P, with stability and admissibility (UsageError if none).
std::vector<Equilibrium> user_profile_equilibria(const Profile& profile, double P);

// CSV bodies with their header lines; InadmissibleError if p < 0 somewhere in the zone.
std::string user_profile_pressure(const Profile& profile, double a, const std::vector<double>& xs);
std::string user_profile_load(const Profile& profile, double a);
std::string user_profile_solve(const Profile& profile, double P);
std::string user_profile_curve(const Profile& profile, int points);

}  // namespace wavecontact::cli
