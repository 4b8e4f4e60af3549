// The figures of `wavecontact reproduce`: each is a CSV table (with a header line) and the
// gnuplot commands that plot it.
#pragma once

#include <string>
#include <vector>

namespace wavecontact::cli {

struct Figure {
  std::string name;     // file stem
  std::string caption;  // what it shows, for REPORT.md
  std::string csv;     // table with a header line
  std::string script;  // gnuplot commands after the terminal/output lines
};

// 10 significant digits, for the tables.
std::string number(double value);

// The gnuplot selector of rows [block * rows, (block + 1) * rows) of a long-format table.
std::string rows_of_block(int block, int rows);

// DIR/REPORT.md: the printed formulas against the exact ones, the snap-through, the figures.
std::string discrepancy_report(const std::vector<Figure>& figures);

// The seed paper's figures.
Figure wave_curves();              // Fig. 1
Figure two_scale_profiles();       // Fig. 2
Figure roughness_integrand();      // Fig. 4
Figure single_asperity_pressure();  // Fig. 5a
Figure periodic_pressure();         // Fig. 5b
Figure contact_length();           // Fig. 6
Figure centre_pressure();          // Fig. 7
Figure two_scale_contact_area();   // Fig. 8

// Beyond the seed: the most uniform pressure (shape design).
Figure shape_design();             // fig9

}  // namespace wavecontact::cli
