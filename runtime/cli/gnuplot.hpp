// Drawing with gnuplot, for `reproduce` and `map --plot`: files written whole, gnuplot run
// without a shell, its PNG checked.
#pragma once

#include <filesystem>
#include <string>

namespace wavecontact::cli {

// Writes `contents` to `path`, replacing it; throws OutputError if it cannot.
void write_file(const std::filesystem::path& path, const std::string& contents);

// The lines that start every script: a PNG terminal writing `png` (a name in the script's
// directory), CSV input, a grid.
std::string gnuplot_preamble(const std::string& png);

// Runs gnuplot on `script` (a file name in `dir`) with `dir` as its working directory, and
// checks that it leaves `png` (a name in `dir`) a whole PNG. An argument vector, no shell, so
// any path works. Throws OutputError if gnuplot cannot run or fails, or the PNG is not whole.
void run_gnuplot(const std::filesystem::path& dir, const std::string& script, const std::string& png);

}  // namespace wavecontact::cli
