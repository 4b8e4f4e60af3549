// Which single-zone solutions of the wave curve are physical and stable, over the whole
// range 0 < a < b1 (docs/mathematics.md facts 8 and 10):
// - admissible: the pressure is >= 0 everywhere in the zone (beyond b1/2 the exact solution
//   can turn negative on the lower flank) and the gap is >= 0 everywhere off it (for m above
//   about 0.7 the valley closes before the load peaks; with roughness, the neighbouring
//   asperities touch). An admissible zone is the contact (wavecontact/contact.hpp): the
//   solution is unique; where none is, the contact has more zones (solve_contact());
// - stable: dP/da > 0. For m above about 0.7 the load is not monotone in a.
#pragma once

#include <functional>
#include <vector>

#include "wavecontact/parameters.hpp"
#include "wavecontact/profile.hpp"

namespace wavecontact {

struct HalfWidthRange {
  double begin, end;  // [length], begin < end
};

struct Admissibility {
  bool admissible;
  double most_negative_x;         // where the pressure is lowest (0 if it is >= 0 everywhere)
  double most_negative_pressure;  // that pressure if negative, else 0
  double lowest_gap;              // the lowest gap off the zone [length]; < 0: penetration
  double x_of_lowest_gap;         // where, x >= 0
};

// The exact pressure of the zone of half-width a, 0 < a < b1, scanned on 128 evenly spaced
// points, 32 between x = b1/2 and a (where it can turn negative) and 10 approaching the edge;
// a pressure below -64 eps p* counts as negative. The gap off the zone by
// wavecontact::single_zone_check() (below -1e-9 of the profile's height range: penetration).
Admissibility admissibility(const WavinessParams& params, double a);

// The same for a user profile, 0 < a < profile.reach(): 128 evenly spaced points and 10
// approaching the edge; a pressure below -64 eps max|p| counts as negative. The gap is
// checked where the profile has no pole on the period (reach() = b1).
Admissibility admissibility(const Profile& profile, double a);

struct Equilibrium {
  double a;  // contact half-width [length]
  bool stable;
  bool admissible;
};

// The load P(a) of one profile over 0 < a <= b1: its turning points (dP/da = 0) are
// located once at construction (a scan of dP/da on 256 points, a Brent search of every
// local minimum of dP/da, TOMS 748 for the roots), so that equilibria() is cheap.
class LoadCurve {
 public:
  explicit LoadCurve(const WavinessParams& params);
  // For a user profile, over 0 < a < profile.reach() (up to b1 when the profile has no pole).
  explicit LoadCurve(const Profile& profile);

  // The ranges of a where dP/da < 0 (snap-through), in increasing order.
  const std::vector<HalfWidthRange>& unstable_ranges() const { return unstable_; }

  // The largest load any single zone carries, and P at the onset of full contact (a = b1;
  // for a profile with a pole, P just short of the pole).
  double maximum_load() const { return maximum_load_; }
  double full_contact_load() const { return full_contact_load_; }

  // Every a in (0, b1) carrying P, in increasing order, each with its stability and
  // admissibility; empty if P > maximum_load().
  std::vector<Equilibrium> equilibria(double P) const;

 private:
  // slope(r), r in (0, 1], has the sign of dP/da at a = r end.
  void locate_turning_points(const std::function<double(double)>& slope);
  std::function<double(double)> load_;
  std::function<bool(double)> admissible_;
  double b1_;                           // the half-period
  double end_;                          // the largest half-width considered
  std::vector<double> turning_points_;  // 0, every a with dP/da = 0, b1
  std::vector<double> turning_loads_;   // P there
  std::vector<HalfWidthRange> unstable_;
  double maximum_load_ = 0, full_contact_load_ = 0;
};

// The one half-width carrying P. Throws std::domain_error if P exceeds every single-zone
// load (full contact), or if several half-widths carry it (listing them: use
// LoadCurve::equilibria()).
double contact_half_width(const WavinessParams& params, double P);

// The same for pa/p* = P / (pi E* H1).
double contact_half_width_for_pa_over_pstar(const WavinessParams& params, double ratio);

// The one half-width carrying P on a user profile (as above).
double contact_half_width(const Profile& profile, double P);

}  // namespace wavecontact
