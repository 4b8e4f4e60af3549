// `wavecontact reproduce --out DIR`: CSV tables and PNG plots (gnuplot) of the seed
// paper's figures, exact and printed forms side by side where they differ.
#pragma once

#include <ostream>
#include <string>

namespace wavecontact::cli {

// Writes DIR/figN.csv, DIR/figN.gp and DIR/figN.png; progress goes to `log`.
// Throws std::runtime_error if a file cannot be written or gnuplot fails.
void reproduce(const std::string& out_dir, std::ostream& log);

}  // namespace wavecontact::cli
