// Maps of shape and scale (map.hpp), for python/wavecontact/maps.py: a whole map on this
// machine's cores, or one load line (the task that maps.py hands to a Dask worker).
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "wavecontact/map.hpp"

namespace wavecontact::python {

namespace {

using Roughnesses = std::vector<std::vector<std::pair<double, int>>>;  // (H, n) of each harmonic

MapGrid grid_of(double H1, double b1, double E, std::vector<double> m, std::vector<double> H2, std::vector<int> n,
                const Roughnesses& harmonics, std::vector<double> loads, bool ratios) {
  MapGrid grid;
  grid.waviness = {H1, b1, m.empty() ? 0.0 : m.front(), E};
  grid.m = std::move(m), grid.H2 = std::move(H2), grid.n = std::move(n), grid.loads = std::move(loads);
  for (const auto& roughness : harmonics) {
    grid.harmonics.emplace_back();
    for (const auto& [H, ratio] : roughness) grid.harmonics.back().push_back({H, ratio});
  }
  grid.loads_are_ratios = ratios;
  validate(grid, "wavecontact.map");
  return grid;
}

// The columns of maps.py's MapResult, one entry a point, by index; unset rows keep status -1.
struct Columns {
  explicit Columns(std::size_t count)
      : status(count, -1),
        zones(count, 0),
        fraction(count),
        p0(count),
        max_p(count),
        estimate(count),
        messages(count) {}
  void set(const MapPoint& p, std::size_t at) {
    status[at] = static_cast<int>(p.status), zones[at] = p.zones, fraction[at] = p.contact_fraction;
    p0[at] = p.p0, max_p[at] = p.max_p, estimate[at] = p.error_estimate, messages[at] = p.message;
  }
  py::tuple to_python() const {
    return py::make_tuple(py::array(py::cast(status)), py::array(py::cast(zones)), py::array(py::cast(fraction)),
                          py::array(py::cast(p0)), py::array(py::cast(max_p)), py::array(py::cast(estimate)), messages);
  }
  std::vector<int> status, zones;
  std::vector<double> fraction, p0, max_p, estimate;
  std::vector<std::string> messages;
};

}  // namespace

void bind_map(py::module_& m) {
  using namespace py::literals;
  m.def(
      "_map_contacts",
      [](double H1, double b1, double E, std::vector<double> shapes, std::vector<double> H2, std::vector<int> n,
         const Roughnesses& harmonics, std::vector<double> loads, bool ratios, double tolerance, double max_seconds,
         unsigned threads) {
        const MapGrid grid =
            grid_of(H1, b1, E, std::move(shapes), std::move(H2), std::move(n), harmonics, std::move(loads), ratios);
        Columns columns(grid.point_count());
        {
          py::gil_scoped_release release;
          MapOptions options;
          options.solver = SolverOptions(tolerance, 0, max_seconds);
          options.threads = threads;
          map_contacts(grid, options, {}, [&](const std::vector<MapPoint>& line) {
            for (const MapPoint& p : line) columns.set(p, p.index);
          });
        }
        return columns.to_python();
      },
      "H1"_a, "b1"_a, "E"_a, "m"_a, "H2"_a, "n"_a, "harmonics"_a, "loads"_a, "ratios"_a, "tolerance"_a, "max_seconds"_a,
      "threads"_a, "Every point of the map on `threads` threads (0: one a core): the columns, by index.");
  m.def(
      "_map_lines_costliest_first",
      [](double H1, double b1, double E, std::vector<double> shapes, std::vector<double> H2, std::vector<int> n,
         const Roughnesses& harmonics, std::vector<double> loads, bool ratios, double, double) {
        return grid_of(H1, b1, E, std::move(shapes), std::move(H2), std::move(n), harmonics, std::move(loads), ratios)
            .lines_costliest_first();
      },
      "H1"_a, "b1"_a, "E"_a, "m"_a, "H2"_a, "n"_a, "harmonics"_a, "loads"_a, "ratios"_a, "tolerance"_a, "max_seconds"_a,
      "The map's load lines, once its grid is checked, in the order the local map takes them.");
  m.def(
      "_solve_map_line",
      [](double H1, double b1, double E, std::vector<double> shapes, std::vector<double> H2, std::vector<int> n,
         const Roughnesses& harmonics, std::vector<double> loads, bool ratios, double tolerance, double max_seconds,
         std::size_t line) {
        const MapGrid grid =
            grid_of(H1, b1, E, std::move(shapes), std::move(H2), std::move(n), harmonics, std::move(loads), ratios);
        if (line >= grid.line_count()) throw py::index_error("wavecontact.map: no line " + std::to_string(line));
        Columns columns(grid.loads.size());
        {
          py::gil_scoped_release release;
          const std::vector<MapPoint> points = solve_map_line(grid, line, SolverOptions(tolerance, 0, max_seconds));
          for (std::size_t k = 0; k < points.size(); ++k) columns.set(points[k], k);
        }
        return columns.to_python();
      },
      "H1"_a, "b1"_a, "E"_a, "m"_a, "H2"_a, "n"_a, "harmonics"_a, "loads"_a, "ratios"_a, "tolerance"_a, "max_seconds"_a,
      "line"_a, "One load line of the map: its columns.");
}

}  // namespace wavecontact::python
