// One contact zone |x| <= a of the wave curve (seed eq. 2), prepared once for many
// evaluations: what depends on (params, a) alone (the zone's angles, and beyond b1/2 the atoms
// of the closed forms on both sides of the kink) is computed by the constructor, so that a
// point costs only its own angles and terms.
// - Up to b1/2 its values are those of the free functions of waviness.hpp, bit for bit (they
//   build the same evaluation per call), from a point or an array alike.
// - Beyond b1/2, near the other branch's pole, a point needs atoms of its own (the Cauchy
//   part's, series of hundreds of terms, about 2 us). AtomTables chooses how the zone takes
//   them (below).
#pragma once

#include <memory>

#include <Eigen/Core>

#include "wavecontact/angles.hpp"
#include "wavecontact/parameters.hpp"

namespace wavecontact {

namespace detail {
class BeyondHalfZone;
}

// Beyond b1/2, how a zone takes the atoms of the points near the other branch's pole.
enum class AtomTables {
  // Tabulated in log(1 + y), a panel of 16 Chebyshev nodes the first time a point falls into it
  // (some tens of microseconds, once), read from it afterwards (about 0.1 us a point). The
  // values are then a function of x alone, the same from a point or an array and from any
  // thread, and differ from the free functions' by the rounding of the atoms
  // (tests/waviness_zone_test.cpp; tests/accuracy_test.cpp against 40-digit references).
  kept,
  // As the free functions of waviness.hpp take them, and so their values bit for bit: computed
  // for each point, and tabulated for one array call where it has at least 16 points in a panel.
  per_call,
};

class WavinessZone {
 public:
  // 0 < a < b1 (std::domain_error otherwise, as wavecontact::pressure).
  WavinessZone(const WavinessParams& params, double a, Form form = Form::exact, AtomTables tables = AtomTables::kept);

  // p(x) [pressure]; x is taken modulo the period 2 b1, 0 off the zone.
  double pressure(double x) const;
  // The same at every point of x (the array kernels of waviness.hpp's pressure()).
  Eigen::ArrayXd pressure(const Eigen::Ref<const Eigen::ArrayXd>& x) const;
  // The same into p (p.size() == x.size()), without allocating.
  void pressure(const Eigen::Ref<const Eigen::ArrayXd>& x, Eigen::Ref<Eigen::ArrayXd> p) const;

  const WavinessParams& params() const { return params_; }
  double half_width() const { return a_; }
  Form form() const { return form_; }
  AtomTables atom_tables() const { return tables_; }

 private:
  friend void pressure(const WavinessParams&, double, const Eigen::Ref<const Eigen::ArrayXd>&,
                       Eigen::Ref<Eigen::ArrayXd>, Form);
  // The zone, its refusals naming `function` (the free functions' own names).
  WavinessZone(const char* function, const WavinessParams& params, double a, Form form, AtomTables tables);
  // The array evaluation, its refusals naming `function`.
  void fill(const char* function, const Eigen::Ref<const Eigen::ArrayXd>& x, Eigen::Ref<Eigen::ArrayXd> p) const;

  WavinessParams params_;
  double a_;
  Form form_;
  AtomTables tables_;
  ZoneAngles angles_;
  double sin_a_;  // sin(pi a/b1), for the array kernels' arithmetic
  bool kernels_;  // a <= b1/2: points and arrays by the array kernels' arithmetic
  std::shared_ptr<const detail::BeyondHalfZone> beyond_half_;  // the exact form beyond b1/2, tables kept; else null
};

}  // namespace wavecontact
