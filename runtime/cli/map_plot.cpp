#include "map_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>

#include "figure.hpp"
#include "gnuplot.hpp"
#include "heat_map.hpp"
#include "map_command.hpp"
#include "refusals.hpp"

namespace wavecontact::cli {

namespace fs = std::filesystem;

namespace {

// The columns a heat map can show: the numbers of a solved point.
const std::vector<std::string> plotted_columns{"zones", "contact_fraction", "p0", "max_p", "error_estimate"};

std::size_t position_of(const std::vector<std::string>& names, const std::string& name) {
  return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
}

// The point's position on each axis, in the order of `axes` (m, the roughness's axes, the load).
std::vector<std::size_t> positions(const MapGrid& grid, const std::vector<MapAxis>& axes, std::size_t index) {
  const std::size_t line = index / grid.loads.size(), r = line % grid.roughness_count();
  std::vector<std::size_t> at;
  for (const MapAxis& a : axes) {
    if (a.name == "m")
      at.push_back(line / grid.roughness_count());
    else if (a.name == "H2")
      at.push_back(r / grid.n.size());
    else if (a.name == "n")
      at.push_back(r % grid.n.size());
    else if (a.name == "harmonics")
      at.push_back(r);
    else
      at.push_back(index % grid.loads.size());
  }
  return at;
}

std::string label(const MapAxis& axis) {
  if (axis.name == "harmonics") return "roughness (its place in --harmonics, from 0)";
  if (axis.name == "pa-over-pstar") return "pa / p*";
  return axis.name;
}

}  // namespace

void MapPlotArguments::add_to(CLI::App* app) {
  auto* column_option = app->add_option("--plot", column,
                                        "draw a heat map of this column (zones, contact_fraction, p0, max_p, "
                                        "error_estimate) with gnuplot, beside --out");
  auto* x_option = app->add_option("--x", x, "the heat map's horizontal axis (m, H2, n, harmonics, pa-over-pstar, P)");
  auto* y_option = app->add_option("--y", y, "its vertical axis");
  // The load axis answers to its option's name and to its column's, pa_over_pstar.
  for (CLI::Option* axis : {x_option, y_option}) {
    axis->transform([](std::string name) { return name == "pa_over_pstar" ? std::string("pa-over-pstar") : name; });
  }
  column_option->needs(x_option, y_option);
  x_option->needs(column_option);
  y_option->needs(column_option);
}

void MapPlotArguments::check(const std::vector<MapAxis>& axes) const {
  if (std::find(plotted_columns.begin(), plotted_columns.end(), column) == plotted_columns.end()) {
    std::string list;
    for (const std::string& c : plotted_columns) list += (list.empty() ? "" : ", ") + c;
    throw UsageError("--plot: no column \"" + column + "\" to draw (one of: " + list + ")");
  }
  if (x == y) throw UsageError("--x and --y are both " + x + ": a heat map needs two axes");
  std::string names;
  for (const MapAxis& a : axes) names += (names.empty() ? "" : ", ") + a.name;
  for (const std::string* name : {&x, &y}) {
    const auto a = std::find_if(axes.begin(), axes.end(), [&](const MapAxis& axis) { return axis.name == *name; });
    if (a == axes.end()) throw UsageError("--plot: this map has no axis \"" + *name + "\" (its axes: " + names + ")");
    if (a->values.size() < 2) {
      throw UsageError("--plot: the axis " + *name + " holds one value; a heat map needs two or more on each axis");
    }
  }
  for (const MapAxis& a : axes) {
    if (a.name != x && a.name != y && a.values.size() > 1) {
      throw UsageError("--plot: the axis " + a.name + " holds " + std::to_string(a.values.size()) +
                       " values; a heat map over " + x + " and " + y + " needs every other axis to hold one");
    }
  }
}

std::string draw_map_plot(const MapPlotArguments& plot, const MapGrid& grid, const std::vector<MapAxis>& axes,
                          const std::string& out) {
  std::size_t x_at = 0, y_at = 0;  // check() found both
  for (std::size_t k = 0; k < axes.size(); ++k) {
    if (axes[k].name == plot.x) x_at = k;
    if (axes[k].name == plot.y) y_at = k;
  }
  const MapAxis &x = axes[x_at], &y = axes[y_at];
  HeatMap map{{label(x), x.values, x.log},
              {label(y), y.values, y.log},
              std::vector<double>(x.values.size() * y.values.size(), std::numeric_limits<double>::quiet_NaN())};
  std::ifstream in(out, std::ios::binary);
  const std::vector<std::string> names = split(map_columns, ',');
  const std::size_t column = position_of(names, plot.column), status = position_of(names, "status");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("index,", 0) == 0) continue;
    const std::vector<std::string> row = split(line, ',');
    if (row.size() <= column || row[status] != "solved") continue;
    const std::vector<std::size_t> at = positions(grid, axes, std::strtoull(row[0].c_str(), nullptr, 10));
    map.z[at[x_at] * y.values.size() + at[y_at]] = std::strtod(row[column].c_str(), nullptr);
  }
  fs::path stem(out);
  if (stem.extension() == ".csv") stem.replace_extension();
  const std::string base = stem.filename().string() + "-" + plot.column;
  const fs::path dir = stem.parent_path().empty() ? fs::path(".") : stem.parent_path();
  std::string fixed;
  for (const MapAxis& a : axes) {
    if (a.name != plot.x && a.name != plot.y) {
      fixed += (fixed.empty() ? ", " : "; ") + a.name + " = " + number(a.values.front());
    }
  }
  write_file(dir / (base + ".csv"), "# " + plot.x + "," + plot.y + "," + plot.column + "\n" + heat_map_table(map));
  write_file(dir / (base + ".gp"), gnuplot_preamble(base + ".png") + "set title '" + plot.column + " over " + plot.x +
                                       " and " + plot.y + fixed + " (blank: not solved)' noenhanced\n" +
                                       heat_map_plot(base + ".csv", 0, map, plot.column, {}));
  run_gnuplot(dir, base + ".gp", base + ".png");
  return (stem.parent_path() / (base + ".png")).string();
}

}  // namespace wavecontact::cli
