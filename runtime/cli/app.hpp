// The wavecontact command line as a function (used by main() and by the fuzz target).
#pragma once

#include <ostream>

namespace wavecontact::cli {

// Runs the command line argv[0..argc): CSV on `out`, diagnostics on `err`. Returns the exit
// status: 0 success, 1 internal error, 2 bad argument, 3 no admissible single-zone
// solution. With allow_files = false, `reproduce` (which writes files and runs gnuplot) is
// refused.
int run(int argc, const char* const* argv, std::ostream& out, std::ostream& err,
        bool allow_files = true);

}  // namespace wavecontact::cli
