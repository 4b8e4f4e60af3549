// fig13, beyond the seed: its effect of scale as a map. The contact fraction over the
// roughness's wavelength ratio n and the load, at the wave curve's m = 0 and m = 10, the
// roughness's slope fixed (H2 n = 1.2 mm, the seed's H2 = 0.15 mm at n = 8), so that only its
// scale changes.
#include <cmath>
#include <vector>

#include "figure.hpp"
#include "heat_map.hpp"
#include "wavecontact/map.hpp"

namespace wavecontact::cli {

Figure scale_map() {
  constexpr double slope = 1.2;  // H2 n [mm]
  const std::vector<int> ns{4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128, 192, 256};
  MapGrid grid;
  grid.waviness = {1.0, 10.0, 0.0, 1.0};  // H1 = 1 mm, b1 = 10 mm, pressures in E*
  grid.m = {0.0, 10.0};
  for (int n : ns) grid.harmonics.push_back({{slope / n, n}});
  for (int i = 1; i <= 20; ++i) grid.loads.push_back(0.1 * i);
  grid.loads_are_ratios = true;
  MapOptions options;
  // Hundreds of zones at n = 256: 1e-8 (their rounding is about 1e-10); an hour a load, as
  // the other figures (computed beside them, the wall clock depends on the machine).
  options.solver = SolverOptions(1e-8, 0, 3600);
  std::vector<double> fraction(grid.point_count(), std::nan(""));
  map_contacts(grid, options, {}, [&](const std::vector<MapPoint>& line) {
    for (const MapPoint& p : line) {
      if (p.status == MapStatus::solved) fraction[p.index] = p.contact_fraction;
    }
  });
  std::string csv = "# n,pa_over_pstar,contact_fraction (a table for m = 0, a blank line, one for m = 10)\n";
  std::string script =
      "set multiplot layout 1,2 title 'fig13: contact fraction at a fixed roughness slope H2 n = " + number(slope) +
      " mm (H1 = 1 mm, b1 = 10 mm; contours every 0.1; blank: not solved)'\n";
  const std::size_t per_m = ns.size() * grid.loads.size();
  for (std::size_t k = 0; k < grid.m.size(); ++k) {
    HeatMap map{{"n (H2 = " + number(slope) + " mm / n)", {}, true}, {"pa / p*", grid.loads, false}, {}};
    for (int n : ns) map.x.values.push_back(n);
    map.z.assign(fraction.begin() + static_cast<std::ptrdiff_t>(k * per_m),
                 fraction.begin() + static_cast<std::ptrdiff_t>((k + 1) * per_m));
    csv += (k ? "\n" : "") + heat_map_table(map);
    script += "set title 'm = " + number(grid.m[k]) + "'\n" +
              heat_map_plot("fig13.csv", static_cast<int>(k), map, "contact fraction",
                            {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9}, 0, 1);
  }
  return {"fig13",
          "fig13: the contact fraction over the roughness's scale n and the load pa/p*, at a fixed roughness slope "
          "(H2 n = 1.2 mm), for the wave curve m = 0 and m = 10",
          csv, script + "unset multiplot\n"};
}

}  // namespace wavecontact::cli
