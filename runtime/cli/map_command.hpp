// `wavecontact map`: the contact over a grid of m, H2, n and the load (wavecontact/map.hpp),
// streamed to a CSV file that a rerun completes (docs/maps.md).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "map_plot.hpp"
#include "wavecontact/map.hpp"

namespace wavecontact::cli {

// The parts of `text` between separators (a trailing separator ends with an empty part).
std::vector<std::string> split(const std::string& text, char separator);

// The values of an axis: "start:stop:count" (evenly spaced, both ends included),
// "start:stop:count:log" (geometrically) or a comma list; `name` for the refusals.
std::vector<double> axis_values(const std::string& name, const std::string& text);

// The columns of a map file.
inline constexpr const char* map_columns =
    "index,m,H2,n,harmonics,P,pa_over_pstar,status,zones,contact_fraction,p0,max_p,error_estimate,message";

struct MapArguments {
  double H1 = 0, b1 = 0, E = 0;
  std::string m = "0", H2, n, harmonics, pa_over_pstar, P, out;
  MapPlotArguments plot;
  double tolerance = 1e-10, max_seconds = 60;
  unsigned threads = 0;
  bool force = false;

  void add_to(CLI::App* app);
  // The grid the options describe (checked: axes, sizes, the library's domains).
  MapGrid grid() const;
  // The grid's axes, in the order of its points' numbering (m, the roughness's, the load).
  std::vector<MapAxis> axes(const MapGrid& grid) const;
  // The lines the header of `out` names, in the order of its columns.
  std::vector<std::string> header() const;
};

// The most points without --force.
inline constexpr std::size_t most_map_points = 100000;

// Solves the map into options.out: the points already there skipped, each line's rows
// appended as it completes; progress on `err` when it is a terminal. The summary line
// (points solved, skipped, beyond reach) is returned; points beyond reach or above the
// tolerance end in NotWithinTolerance (exit status 4) once every point is written.
std::string run_map(const MapArguments& options, std::ostream& err);

}  // namespace wavecontact::cli
