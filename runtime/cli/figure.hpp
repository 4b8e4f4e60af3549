// The figures of `wavecontact reproduce`: each is a CSV table (with a header line) and the
// gnuplot commands that plot it.
#pragma once

#include <string>
#include <vector>

#include "wavecontact/contact.hpp"

namespace wavecontact::cli {

struct Figure {
  std::string name;     // file stem
  std::string caption;  // what it shows, for REPORT.md
  std::string csv;      // table with a header line
  std::string script;   // gnuplot commands after the terminal/output lines
};

// 10 significant digits, for the tables.
std::string number(double value);

// The gnuplot selector of rows [block * rows, (block + 1) * rows) of a long-format table.
std::string rows_of_block(int block, int rows);

// The seed's two-scale parameters of Figs. 7 and 8: H1 = 1 mm, H2 = 0.15 mm, b1 = 10 mm.
inline constexpr double two_scale_H2 = 0.15;

// The contact of the two-scale profile (the seed's H2, each n of ns; m = 0, 10) over a sweep
// of `count` loads pa/p* up to `top`, denser at small loads: n = 8, 16 to 1.2 are shared by
// Fig. 7, fig10 and REPORT.md; fig10 adds n = 64, 256 to 2.
struct TwoScaleSweep {
  int n;
  double m;
  std::vector<double> ratios;  // pa/p*
  std::vector<Contact> contacts;
};
using TwoScaleSweeps = std::vector<TwoScaleSweep>;
TwoScaleSweeps two_scale_sweeps(const std::vector<int>& ns, double top, int count);

// DIR/REPORT.md: the printed formulas against the exact ones, the single zone against the
// contact, the snap-through, the figures.
std::string discrepancy_report(const std::vector<Figure>& figures, const TwoScaleSweeps& sweeps);

// The seed paper's figures.
Figure wave_curves();                                  // Fig. 1
Figure two_scale_profiles();                           // Fig. 2
Figure roughness_integrand();                          // Fig. 4
Figure single_asperity_pressure();                     // Fig. 5a
Figure periodic_pressure();                            // Fig. 5b
Figure contact_length();                               // Fig. 6, to full contact
Figure centre_pressure(const TwoScaleSweeps& sweeps);  // Fig. 7, every load
Figure two_scale_contact_area();                       // Fig. 8

// Beyond the seed: the most uniform pressure (shape design), the contact fraction and zones
// per period of the two-scale profile, the pressure at a multi-zone load, four scales.
Figure shape_design();                                            // fig9
Figure contact_fraction_and_zones(const TwoScaleSweeps& sweeps);  // fig10
Figure multi_zone_pressure();                                     // fig11
Figure four_scale_contact();                                      // fig12
Figure scale_map();  // fig13: the contact fraction over (n, pa/p*) at a fixed roughness slope

}  // namespace wavecontact::cli
