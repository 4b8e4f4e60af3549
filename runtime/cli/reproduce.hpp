// `wavecontact reproduce --out DIR`: CSV tables and PNG plots (gnuplot) of the seed
// paper's figures, exact and printed forms side by side where they differ.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace wavecontact::cli {

// Writes DIR/figN.csv, DIR/figN.gp and DIR/figN.png (of the figures named in `only`, or all
// of them and DIR/REPORT.md); progress goes to `log`.
// Throws OutputError (refusals.hpp) if a file cannot be written, gnuplot fails or leaves a
// PNG that is not whole.
void reproduce(const std::string& out_dir, const std::vector<std::string>& only, std::ostream& log);

}  // namespace wavecontact::cli
