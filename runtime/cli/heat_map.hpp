// A heat map with contour lines (gnuplot's splot in map view), for fig13 of `reproduce` and
// for `map --plot`.
#pragma once

#include <string>
#include <vector>

namespace wavecontact::cli {

struct HeatMapAxis {
  std::string label;           // the axis's title
  std::vector<double> values;  // ascending, at least two
  bool log = false;            // drawn on a log scale
};

struct HeatMap {
  HeatMapAxis x, y;
  std::vector<double> z;  // at (x_i, y_j): z[i * y.values.size() + j]; NaN where there is none
};

// The rows "x,y,z" of a heat map, in scans of constant x with a blank line after each (the
// grid gnuplot's pm3d draws); tables of several maps are joined by one more blank line, and
// gnuplot's `index` picks one.
std::string heat_map_table(const HeatMap& map);

// The commands that draw table `index` of `file` as a heat map of `z_label` over the map's
// axes, with contour lines at `levels` (empty: ten levels that gnuplot chooses) and the colour
// range [z_low, z_high] (equal: the data's).
std::string heat_map_plot(const std::string& file, int index, const HeatMap& map, const std::string& z_label,
                          const std::vector<double>& levels, double z_low = 0, double z_high = 0);

}  // namespace wavecontact::cli
