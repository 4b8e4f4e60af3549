// What wavecontact-derive writes: the emitted evaluators and the manifest of every
// derived expression, as file contents (the caller writes them).
#pragma once

#include <string>
#include <vector>

#include "formulas/user_profile.hpp"

namespace wavecontact::derive {

struct GeneratedFile {
  std::string name;  // relative to the output directory
  std::string contents;
};

// The command that regenerates the committed generated/ directory; named in every
// file's banner.
std::string regeneration_command();

// The n that generated/ ships: every even n from 2 to 64, 128 and 256.
std::vector<int> default_roughness_n();

// Everything in generated/: the waviness, the roughness evaluators for the default n
// with their registry, the example profiles with theirs, and the manifests.
std::vector<GeneratedFile> generate_all();

// roughness_n<N>.hpp for each requested n (wavecontact-derive --n N ... --out DIR).
// Throws std::invalid_argument unless every n is even, 2 <= n <= 4096.
std::vector<GeneratedFile> generate_roughness(const std::vector<int>& ns);

// profile_<name>.hpp and profile_<name>_manifest.txt for a user profile
// (wavecontact-derive --profile EXPR --name NAME); command goes into their banners.
// Throws std::invalid_argument as derive_profile() does.
std::vector<GeneratedFile> generate_profile(const ProfileSpec& spec, const std::string& command);

// The example profiles in generated/: the parametric wave curve as an expression, and a
// two-harmonic profile H1 cos x + H3 cos 3x.
std::vector<ProfileSpec> example_profiles();

// generated/profiles.hpp: includes every example profile and visits their evaluators.
std::string profile_registry(const std::vector<ProfileSpec>& specs);

}  // namespace wavecontact::derive
