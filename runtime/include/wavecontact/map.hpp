// Maps of shape and scale (docs/maps.md): the contact over a grid of the wave curve's shape
// m, the roughness (one harmonic's height H2 and wavelength ratio n, or a list of whole
// roughnesses) and the load. The loads of one (m, roughness) form a load line, solved by one
// continuation (solve_contact over its loads); the lines run on threads, each line's results
// the same whichever thread or run solves it.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "wavecontact/contact.hpp"
#include "wavecontact/parameters.hpp"

namespace wavecontact {

// The grid: every m with every roughness with every load. The roughnesses are either every
// H2 with every n (one harmonic each), or the list `harmonics`. The points are numbered
// index = line * loads.size() + load, line = m_i * roughness_count() + r, and for H2 and n
// r = H2_j * n.size() + n_k (no roughness counts as one: the wave curve alone).
struct MapGrid {
  WavinessParams waviness;  // H1, b1, E; its m stands where `m` is empty
  std::vector<double> m;
  std::vector<double> H2;  // roughness heights (empty: no roughness)
  std::vector<int> n;      // wavelength ratios (empty with H2 alone)
  // Or, without H2 and n: whole roughnesses, each of one or more harmonics (e.g. one scale a
  // roughness at a fixed slope H2 n, or Weierstrass series of several depths).
  std::vector<std::vector<Harmonic>> harmonics;
  std::vector<double> loads;
  bool loads_are_ratios = false;  // loads as pa/p* (P = pa/p* pi E* H1), else P per period

  std::size_t roughness_count() const;
  std::size_t line_count() const;
  std::size_t point_count() const { return line_count() * loads.size(); }
  // The line's parameters.
  double line_m(std::size_t line) const;
  std::vector<Harmonic> line_roughness(std::size_t line) const;  // empty: the wave curve alone
  // Every line, the finest roughness first (the highest harmonic n, then the largest sum of
  // heights), else in index order: the costliest first as a rule, the order map_contacts
  // takes them in.
  std::vector<std::size_t> lines_costliest_first() const;
};

enum class MapStatus { solved, above_tolerance, beyond_reach };
const char* to_string(MapStatus status);  // "solved", "above_tolerance", "beyond_reach"

struct MapPoint {
  std::size_t index = 0;
  double m = 0;
  std::vector<Harmonic> harmonics;  // the roughness
  double H2 = 0;                    // and its harmonic's height and ratio when it has one,
  int n = 0;                        // else NaN (several) or 0 (none), and 0
  double P = 0, pa_over_pstar = 0;
  MapStatus status = MapStatus::solved;
  // The contact (NaN and 0 beyond reach).
  int zones = 0;
  double contact_fraction = 0, p0 = 0, max_p = 0, error_estimate = 0;
  std::string message;  // why, beyond reach
};

struct MapOptions {
  SolverOptions solver;
  unsigned threads = 0;  // lines solved at once; 0: one a core
};

// Checks the grid (every value finite and in its domain, loads ascending and positive, at
// least one of each, H2 and n or harmonics), naming the parameter and the value; throws std::domain_error.
void validate(const MapGrid& grid, const char* function);

// The points of one line, solved: a line whose continuation fails is solved load by load,
// each failure recorded as beyond_reach with its message; a contact whose estimate misses the
// tolerance as above_tolerance.
std::vector<MapPoint> solve_map_line(const MapGrid& grid, std::size_t line, const SolverOptions& options);

// Solves every line for which skip(line) is false and hands its points to line_done, from
// any thread but one call at a time, taking them in the order of lines_costliest_first. An
// exception of line_done (or of skip) stops the map: the lines in flight finish, no other
// starts, and it is rethrown here.
void map_contacts(const MapGrid& grid, const MapOptions& options, const std::function<bool(std::size_t)>& skip,
                  const std::function<void(const std::vector<MapPoint>&)>& line_done);

}  // namespace wavecontact
