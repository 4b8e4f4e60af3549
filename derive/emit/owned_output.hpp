// Writing generated files into a directory that may hold the user's own files too: only the
// files the tool writes are touched, each replaced in one rename().
#pragma once

#include <filesystem>
#include <stdexcept>
#include <vector>

#include "emit/file_contents.hpp"

namespace wavecontact::derive {

// The output directory is not one the tool may write into (the root, the current or home
// directory, a non-empty directory without a file of ours), or is not a directory.
struct OutputRefused : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// A file could not be written (the directory is then as it was, but for the files already
// replaced, each old or new whole).
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Writes `files` into `directory` (created if missing; a symbolic link is written through).
// Each file is written beside its target as .NAME.tmp-PID and renamed over it, with the
// target's permissions (a build system sees every output renewed); the manifests
// (*manifest.txt) are renamed last, so a complete set is marked by its manifests. Nothing
// else in the directory is read, moved or deleted. Concurrent runs into one directory take
// turns on a lock (flock of the directory). A failed run removes its
// temporary file; those of killed runs (whose PID is gone) are removed by the next run.
// Unless `force`, refuses the root, the current and the home directory, a non-empty
// directory that holds no file written by wavecontact-derive (its banner on the first line),
// and a file to be replaced that does not carry that banner.
void write_generated_files(const std::filesystem::path& directory, const std::vector<GeneratedFile>& files, bool force);

}  // namespace wavecontact::derive
