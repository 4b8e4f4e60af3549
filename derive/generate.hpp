// What wavecontact-derive writes: the emitted evaluators and the manifest of every
// derived expression, as file contents (the caller writes them).
#pragma once

#include <string>
#include <vector>

namespace wavecontact::derive {

struct GeneratedFile {
  std::string name;      // relative to the output directory
  std::string contents;
};

// The command that regenerates the committed generated/ directory; named in every
// file's banner.
std::string regeneration_command();

std::vector<GeneratedFile> generate_all();

}  // namespace wavecontact::derive
