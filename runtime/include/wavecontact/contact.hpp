// The real contact at any load: the unique solution of the frictionless periodic contact
// (p >= 0 on the contact set, gap >= 0 off it; it minimises a strictly convex energy), with
// as many zones per period as it takes, up to full contact.
//
// The surface is the wave curve of eq. 2 with any number of roughness harmonics
// H_i cos(n_i pi x/b1) (eqs. 1, 3), or a user profile (profile.hpp). The zones' ends solve
// the bounded inversion of the finite Hilbert transform on several intervals (Muskhelishvili)
// with one rigid approach for all zones; the zones are found by continuation in the load
// (runtime/src/contact/contact_solver.hpp). Where one zone per period is the solution this is the
// seed's single-zone solution (the closed forms of waviness.hpp, two_scale.hpp, profile.hpp,
// to 1e-10); where it is not, those closed forms are refused (admissibility in stability.hpp).
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "wavecontact/errors.hpp"
#include "wavecontact/parameters.hpp"
#include "wavecontact/profile.hpp"

namespace wavecontact {

namespace detail {
struct SurfaceModel;
class ContactSolution;
}  // namespace detail

struct TwoScaleParams;

// A roughness harmonic H cos(n pi x/b1): H finite (negative: a trough at x = 0), n >= 1.
// A surface takes at most max_harmonics of them, each n <= max_roughness_n (two_scale.hpp).
inline constexpr std::size_t max_harmonics = 16;
struct Harmonic {
  double H;  // [length]
  int n;
};

// Checks a roughness (the count, each H and n), naming `function`, the parameter and the
// value; throws std::domain_error.
void validate(const std::vector<Harmonic>& roughness, const char* function);

// The surface y(x), even and of period 2 b1, pressed against a half-plane of reduced
// modulus E*.
class Surface {
 public:
  // The wave curve plus the harmonics (none: the wave curve alone).
  explicit Surface(const WavinessParams& waviness, const std::vector<Harmonic>& roughness = {});
  // The seed's two-scale profile (eq. 1): one harmonic.
  explicit Surface(const TwoScaleParams& params);
  // A user profile; throws std::domain_error if it has a pole on the period.
  explicit Surface(const Profile& profile);

  double b1() const { return b1_; }
  double E() const { return E_; }
  // y(x) [length], any x.
  double height(double x) const;
  // A bound of max |y| [length]: H1 plus the harmonics' |H| (or max |y| sampled, for a profile).
  double height_scale() const { return height_scale_; }

  // The solver's view of the surface (runtime/src/contact/surface_model.hpp).
  const std::shared_ptr<const detail::SurfaceModel>& model() const { return model_; }

 private:
  std::shared_ptr<const detail::SurfaceModel> model_;
  double b1_, E_, height_scale_ = 0;
};

// One contact zone of the period [-b1, b1). A zone around the valley x = +-b1 is listed
// once, from x_start to x_end = 2 b1 - x_start > b1 (it crosses the period's end).
struct ContactZone {
  double x_start, x_end;     // [length]
  double load;               // the load it carries [pressure x length]
  double max_pressure;       // [pressure]
  double x_of_max_pressure;  // [length]
};

// The smallest load solve_contact takes, relative to E* height_scale(): below it the contact
// is one zone narrower than the resolution of x.
inline constexpr double min_load_ratio = 1e-20;

struct SolverOptions {
  SolverOptions() = default;
  SolverOptions(double tolerance_, int nodes_per_zone_ = 0, double max_seconds_ = 60)
      : tolerance(tolerance_), nodes_per_zone(nodes_per_zone_), max_seconds(max_seconds_) {}

  // The relative error estimate the result must meet (of the pressure, relative to its
  // maximum, and of the zone ends, relative to the period); 1e-14 <= tolerance <= 1e-2.
  double tolerance = 1e-10;
  // The Chebyshev nodes of each zone's density: 0 lets each zone's grow until its tail meets
  // the tolerance (the estimate is against a solve on a quarter more); 4 <= nodes_per_zone
  // <= 4096 fixes them.
  int nodes_per_zone = 0;
  // The work budget of each load: a solve that has not met the tolerance after this many
  // seconds on one load stops with wavecontact::BeyondReach (errors.hpp), saying how far it
  // got; 0 < max_seconds.
  double max_seconds = 60;
  // Called at safe points, about every tenth of a second; may throw to abandon the solve
  // (the exception propagates out of solve_contact).
  std::function<void()> checkpoint;
};

// The contact at one load.
class Contact {
 public:
  double load() const { return P_; }  // P [pressure x length] per period
  // The zones of the period [-b1, b1), in increasing x_start.
  const std::vector<ContactZone>& zones() const { return zones_; }
  int zones_per_period() const { return static_cast<int>(zones_.size()); }
  bool full_contact() const { return full_; }
  // The contact length over the period, 2a/L1 for one zone.
  double contact_fraction() const { return fraction_; }
  double max_pressure() const { return max_pressure_; }
  double x_of_max_pressure() const { return x_of_max_; }

  // p(x) [pressure] and the gap [length] at any x (periodic): 0 off the zones, 0 on them.
  double pressure(double x) const;
  void pressure(const Eigen::Ref<const Eigen::ArrayXd>& x, Eigen::Ref<Eigen::ArrayXd> p) const;
  double gap(double x) const;

  // The estimated relative error of the pressure (to max_pressure()) and of the zone ends
  // (to the period 2 b1): the larger of the change to a solve on more nodes and the
  // rounding error.
  double error_estimate() const { return error_estimate_; }
  // The part of it that rounding alone makes (each zone's load is the T_0 coefficient of a
  // sum of the other zones' potentials and the approach).
  double rounding_error() const { return rounding_; }
  // The most Chebyshev nodes of a zone.
  int nodes_per_zone() const { return nodes_; }

 private:
  friend std::vector<Contact> solve_contact(const Surface&, const std::vector<double>&, const SolverOptions&);
  std::shared_ptr<const detail::ContactSolution> solution_;
  double b1_ = 0, P_ = 0, fraction_ = 0, max_pressure_ = 0, x_of_max_ = 0;
  double error_estimate_ = 0, rounding_ = 0;
  int nodes_ = 0;
  bool full_ = false;
  std::vector<ContactZone> zones_;
};

// The contact carrying the load P > 0 [pressure x length] per period.
Contact solve_contact(const Surface& surface, double P, const SolverOptions& options = {});

// The contacts carrying each load (any order), by one continuation through them in
// increasing load: cheaper than one call per load.
std::vector<Contact> solve_contact(const Surface& surface, const std::vector<double>& loads,
                                   const SolverOptions& options = {});

// The load [pressure x length] from which the contact is full (p >= 0 everywhere with no gap).
double full_contact_load(const Surface& surface);

// Whether one zone |x| < a per period, with the pressure of eq. 12 for it, is the contact:
// p >= 0 on it and gap >= 0 off it (0 < a < b1).
struct SingleZoneCheck {
  bool solution;
  bool penetrates;                               // the gap is below -1e-9 of the height range off the zone
  double lowest_gap, x_of_lowest_gap;            // [length], x >= 0; lowest_gap < 0: penetration
  double lowest_pressure, x_of_lowest_pressure;  // [pressure]
};
SingleZoneCheck single_zone_check(const Surface& surface, double a);

}  // namespace wavecontact
