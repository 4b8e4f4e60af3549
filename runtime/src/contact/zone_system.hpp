// The equations of a contact configuration (docs/contact.md): zones of the half period, each
// with its density's coefficients, and one constant C (the rigid approach). On every zone
// the logarithmic potential of all zones equals (E*/2) (y - y_top) + C at the zone's
// Chebyshev nodes (heights from the top, so that C does not cancel a height at small loads);
// q is bounded at every free end; the zones carry the load P (or, for a given single zone,
// its end conditions alone fix it). Newton's method on ends, coefficients and C together,
// its linear systems by GMRES with a preconditioner that solves each zone exactly with the
// others frozen and couples the zones through their loads (a dense system of one unknown a
// zone): the far fields are smooth and, beyond the loads', small.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "kink_correction.hpp"
#include "surface_model.hpp"
#include "zone.hpp"

namespace wavecontact::detail {

struct ZoneUnknowns {
  ZoneGeometry geometry;
  std::vector<double> d;  // N + 1 coefficients (the zone's nodes: N + 1)
  double birth_load = -1;  // where the continuation saw it open (negative: not known)
};

struct Configuration {
  std::vector<ZoneUnknowns> zones;  // in increasing x^, disjoint
  double C = 0;
};

// What each zone's density is beyond its coefficients d: the kink correction of a zone a
// kink lies in (null for the others).
struct ZoneFields {
  std::vector<std::shared_ptr<const KinkCorrection>> kinks;
};
ZoneFields zone_fields(const SurfaceModel& surface, const Configuration& c);

// The potential of zone k at x^ off it (its kink correction's included).
double zone_potential(const Configuration& c, const ZoneFields& fields, std::size_t k, double x);

// The load of zone k over its part of [0, pi]: pi h d_0, plus its kink correction's.
double zone_load(const Configuration& c, const ZoneFields& fields, std::size_t k);

// What the equations ask of the configuration besides the contact conditions.
struct Closure {
  bool load_given = true;  // the zones carry P; else every zone end is fixed (a given single zone)
  double P = 0;
};

class ZoneSystem {
 public:
  ZoneSystem(const SurfaceModel& surface, Closure closure) : surface_(surface), closure_(closure) {}

  // The potential of every zone but `skip` at the angle x (off them all but skip).
  double field_of_others(const Configuration& c, const ZoneFields& fields, std::size_t skip, double x) const;

  // The coefficients that solve each zone's equations with the others' field and C as they
  // are (one block-Jacobi sweep): a start for a new zone or new node counts.
  void relax(Configuration& c) const;

  // Newton's method from `c` until the scaled residuals are below `tolerance`. Returns the
  // configuration reached and whether it converged; a step that would close a stretch
  // (a zone, a gap between zones, the stretch to the top or the valley) stops it with that
  // stretch named (outcome), for the continuation to change the zones.
  enum class Outcome { converged, stretch_closes, failed };
  struct Result {
    Outcome outcome = Outcome::failed;
    Configuration configuration;
    // For stretch_closes: the stretch between consecutive ends of [0, a_1, b_1, ..., pi].
    std::size_t stretch = 0;
    double residual = 0;  // the largest scaled residual reached
    int iterations = 0;
  };
  Result newton(Configuration c, double tolerance, const std::function<void()>& checkpoint) const;

  // The scaled residuals of c (for tests and for the solver's checks).
  std::vector<double> residuals(const Configuration& c) const;

 private:
  struct Layout;  // the unknowns' places and scales, fixed for one Newton solve
  Layout layout(const Configuration& c) const;
  std::vector<double> pack(const Configuration& c, const Layout& L) const;
  Configuration unpack(const std::vector<double>& X, const Layout& L) const;
  std::vector<double> residual(const Configuration& c, const Layout& L, std::vector<std::vector<double>>* external_slope) const;

  const SurfaceModel& surface_;
  Closure closure_;
};

}  // namespace wavecontact::detail
