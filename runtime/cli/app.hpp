// The wavecontact command line as a function (used by main() and by the fuzz target).
#pragma once

#include <ostream>

namespace wavecontact::cli {

// Runs the command line argv[0..argc): CSV on `out`, diagnostics on `err`. Returns the exit
// status of common/exit_status.hpp: 0 success, 1 internal error (a bug), 2 bad argument,
// 3 the single zone asked for is not the contact, 4 beyond reach (tolerance missed, work
// budget spent), 5 output that cannot be written. With allow_files = false, `reproduce` (which writes files and runs
// gnuplot) is refused.
int run(int argc, const char* const* argv, std::ostream& out, std::ostream& err, bool allow_files = true);

}  // namespace wavecontact::cli
