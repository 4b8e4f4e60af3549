// Writing generated files so that an interrupted run leaves the output directory exactly
// as it was or fully updated.
#pragma once

#include <filesystem>
#include <vector>

#include "generate.hpp"

namespace wavecontact::derive {

// Writes `files` into `directory` atomically as a whole: everything (including what the
// directory already holds and is not overwritten) is assembled in a staging directory
// beside it, which is then exchanged with the directory in one renameat2(RENAME_EXCHANGE)
// (or renamed into place if the directory does not exist yet). Staging directories left
// by killed runs are removed. Throws std::runtime_error on failure.
void write_directory_atomically(const std::filesystem::path& directory,
                                const std::vector<GeneratedFile>& files);

}  // namespace wavecontact::derive
