#include "heat_map.hpp"

#include <cmath>

#include "figure.hpp"

namespace wavecontact::cli {

namespace {

// gnuplot's undefined value where there is none.
std::string text(double value) { return std::isnan(value) ? "NaN" : number(value); }

// The axis's range (at least two values), title and scale, with tics at its values where
// they are few (or, on a log scale, at about ten of them).
std::string axis_commands(const std::string& name, const HeatMapAxis& axis) {
  std::string s = "set " + name + "label '" + axis.label + "' noenhanced\nset " + name + "range [" +
                  text(axis.values.front()) + ":" + text(axis.values.back()) + "]\n";
  s += axis.log ? "set logscale " + name + "\n" : "unset logscale " + name + "\n";
  if (!axis.log && axis.values.size() > 12) return s + "set " + name + "tics autofreq\n";
  s += "set " + name + "tics (";
  const std::size_t every = (axis.values.size() + 11) / 12;
  for (std::size_t i = 0; i < axis.values.size(); i += every) s += (i ? ", " : "") + text(axis.values[i]);
  return s + ")\n";
}

}  // namespace

std::string heat_map_table(const HeatMap& map) {
  std::string table;
  const std::size_t ny = map.y.values.size();
  for (std::size_t i = 0; i < map.x.values.size(); ++i) {
    for (std::size_t j = 0; j < ny; ++j) {
      table += text(map.x.values[i]) + "," + text(map.y.values[j]) + "," + text(map.z[i * ny + j]) + "\n";
    }
    table += "\n";
  }
  return table;
}

std::string heat_map_plot(const std::string& file, int index, const HeatMap& map, const std::string& z_label,
                          const std::vector<double>& levels, double z_low, double z_high) {
  std::string s =
      "set view map\nset key off\nset contour base\nset cntrparam linear\nset cntrlabel onecolor\n"
      "set palette defined (0 '#440154', 0.25 '#3b528b', 0.5 '#21908d', 0.75 '#5dc963', 1 '#fde725')\n";
  if (levels.empty()) {
    s += "set cntrparam levels auto 10\n";
  } else {
    s += "set cntrparam levels discrete ";
    for (std::size_t k = 0; k < levels.size(); ++k) s += (k ? "," : "") + text(levels[k]);
    s += "\n";
  }
  s += axis_commands("x", map.x) + axis_commands("y", map.y);
  s += "set cblabel '" + z_label + "' noenhanced\n";
  s += z_low < z_high ? "set cbrange [" + text(z_low) + ":" + text(z_high) + "]\n" : "set autoscale cb\n";
  const std::string data = "'" + file + "' index " + std::to_string(index) + " using 1:2:3";
  return s + "splot " + data + " with pm3d nocontours notitle, \\\n  " + data +
         " with lines nosurface lc rgb 'white' lw 1 notitle\n";
}

}  // namespace wavecontact::cli
