// `wavecontact map --plot COLUMN --x AXIS --y AXIS`: a heat map of one column of a map file
// over two of its axes, the others holding one value each (docs/maps.md).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "wavecontact/map.hpp"

namespace wavecontact::cli {

// An axis of a map: its name as the options spell it (m, H2, n, harmonics, pa-over-pstar or
// P), its values (for harmonics, the roughnesses' positions 0, 1, ...) and whether it was
// given as a log range.
struct MapAxis {
  std::string name;
  std::vector<double> values;
  bool log = false;
};

struct MapPlotArguments {
  std::string column, x, y;

  void add_to(CLI::App* app);
  bool wanted() const { return !column.empty(); }
  // Refuses (UsageError) a column that is not a number, axes that the map does not have or
  // that hold one value, and other axes that hold more than one.
  void check(const std::vector<MapAxis>& axes) const;
};

// Draws the plot from the map file `out` (complete: every point has its row): writes
// STEM-COLUMN.csv (the table), .gp and .png next to it, STEM being `out` without ".csv".
// Returns the PNG's path; throws OutputError if a file cannot be written or gnuplot fails.
std::string draw_map_plot(const MapPlotArguments& plot, const MapGrid& grid, const std::vector<MapAxis>& axes,
                          const std::string& out);

}  // namespace wavecontact::cli
