// The pressure of one zone of the wave curve (waviness_zone.hpp), and waviness.hpp's free
// pressure functions, which evaluate through it.
#include "wavecontact/waviness_zone.hpp"

#include <cmath>

#include "closed_forms/periodic_regime.hpp"
#include "kernels/pressure_simd.hpp"
#include "support/parallel.hpp"
#include "support/validate.hpp"
#include "wavecontact/generated/waviness_evaluators.hpp"
#include "wavecontact/threads.hpp"
#include "wavecontact/waviness.hpp"

namespace wavecontact {

namespace {

// p at x: the generated closed form (exact up to b1/2, or the printed eq. 13/14), and beyond
// b1/2 the exact one from the atoms of the point's own side of the kink, computed here.
double pressure_at(const WavinessParams& p, double a, const ZoneAngles& zone, double x, Form form) {
  const double r = std::fabs(reduce_to_period(x, p.b1));
  if (r >= a) return 0;
  const PointAngles point = point_angles(r, a, p.b1);
  if (form == Form::exact && a > p.b1 / 2) return detail::pressure_beyond_half(p, zone, point);
  return form == Form::exact
             ? generated::waviness_pressure_exact(p.E, p.H1, p.b1, p.m, zone.Ca, zone.Sa, point.Cx, point.Sx, point.D)
             : generated::waviness_pressure_paper(p.E, p.H1, p.b1, p.m, zone.Ca, zone.Sa, point.Cx, point.Sx, point.D);
}

// Below this many points an array is evaluated point by point (kernel_point).
constexpr std::size_t few_points = detail::simd_block / 8;

// The zone for the array kernels (a <= b1/2).
detail::SimdWavinessZone simd_zone(const WavinessParams& p, double a, const ZoneAngles& zone, double sin_a) {
  return {p.E, p.H1, p.b1, p.m, a, zone.Ca, zone.Sa, sin_a};
}

double sine_of(const ZoneAngles& zone) { return std::sqrt(zone.Sa * (1 + zone.Ca)); }

// Up to a = b1/2 (the kernels' bounded arguments), points and arrays take the array kernels'
// arithmetic (the same atoms and closed form, compiled for array_kernel_isa()), one point
// with x reduced to the period exactly first. Beyond, a point takes pressure_at, as the free
// function does, unless the zone keeps its tables of atoms (AtomTables::kept).
bool kernels_serve(const WavinessParams& p, double a) { return a <= p.b1 / 2; }
double kernel_point(const detail::SimdWavinessZone& zone, Form form, double x) {
  return detail::simd_point_pressure(zone, form, std::fabs(x) <= zone.b1 ? x : reduce_to_period(x, zone.b1));
}

}  // namespace

WavinessZone::WavinessZone(const WavinessParams& params, double a, Form form, AtomTables tables)
    : WavinessZone("wavecontact::WavinessZone", params, a, form, tables) {}

WavinessZone::WavinessZone(const char* function, const WavinessParams& params, double a, Form form, AtomTables tables)
    : params_(params), a_(a), form_(form), tables_(tables) {
  validate(params, function);
  detail::require_waviness_half_width(function, params, a, form);
  angles_ = zone_angles(a, params.b1);
  sin_a_ = sine_of(angles_);
  kernels_ = kernels_serve(params, a);
  if (form == Form::exact && a > params.b1 / 2 && tables == AtomTables::kept)
    beyond_half_ = std::make_shared<detail::BeyondHalfZone>(params, a, angles_, true);
}

double WavinessZone::pressure(double x) const {
  detail::require_finite("wavecontact::WavinessZone::pressure", "x", x);
  if (kernels_) return kernel_point(simd_zone(params_, a_, angles_, sin_a_), form_, x);
  if (beyond_half_) return beyond_half_->pressure(x);
  return pressure_at(params_, a_, angles_, x, form_);
}

void WavinessZone::pressure(const Eigen::Ref<const Eigen::ArrayXd>& x, Eigen::Ref<Eigen::ArrayXd> p) const {
  fill("wavecontact::WavinessZone::pressure", x, p);
}

Eigen::ArrayXd WavinessZone::pressure(const Eigen::Ref<const Eigen::ArrayXd>& x) const {
  Eigen::ArrayXd p(x.size());
  fill("wavecontact::WavinessZone::pressure", x, p);
  return p;
}

void WavinessZone::fill(const char* function, const Eigen::Ref<const Eigen::ArrayXd>& x,
                        Eigen::Ref<Eigen::ArrayXd> p) const {
  detail::require_same_size(function, x, p.size());
  const auto count = static_cast<std::size_t>(x.size());
  const double* xs = x.data();
  double* ps = p.data();
  if (form_ == Form::exact && !kernels_) {  // beyond b1/2: tables kept, or the call's own
    detail::require_finite_points(function, x);
    if (beyond_half_) {
      beyond_half_->pressures(xs, ps, count, parallel_points_costly);
    } else {
      detail::BeyondHalfZone(params_, a_, angles_, false).pressures(xs, ps, count, parallel_points_costly);
    }
    return;
  }
  const detail::SimdWavinessZone zone = simd_zone(params_, a_, angles_, sin_a_);
  // A few points: one at a time (a block of the array kernels costs 256 points' work).
  if (kernels_ && count < few_points) {
    for (std::size_t i = 0; i < count; ++i) detail::require_finite(function, "x", xs[i]);
    for (std::size_t i = 0; i < count; ++i) ps[i] = kernel_point(zone, form_, xs[i]);
    return;
  }
  // The points are checked in the threads, before any is computed.
  const bool finite = detail::for_each_chunk(
      count, detail::simd_block, parallel_points,
      [xs](std::size_t begin, std::size_t end) { return detail::all_finite(xs + begin, end - begin); },
      [&](std::size_t begin, std::size_t end) {
        if (kernels_) {
          detail::simd_pressure(zone, form_, xs + begin, ps + begin, end - begin);
        } else {
          for (std::size_t i = begin; i < end; ++i) ps[i] = pressure(xs[i]);
        }
      });
  if (!finite) detail::require_finite_points(function, x);
}

double pressure(const WavinessParams& params, double a, double x, Form form) {
  constexpr const char* function = "wavecontact::pressure";
  validate(params, function);
  detail::require_waviness_half_width(function, params, a, form);
  detail::require_finite(function, "x", x);
  const ZoneAngles zone = zone_angles(a, params.b1);
  if (kernels_serve(params, a)) return kernel_point(simd_zone(params, a, zone, sine_of(zone)), form, x);
  return pressure_at(params, a, zone, x, form);
}

void pressure(const WavinessParams& params, double a, const Eigen::Ref<const Eigen::ArrayXd>& x,
              Eigen::Ref<Eigen::ArrayXd> p, Form form) {
  constexpr const char* function = "wavecontact::pressure";
  WavinessZone(function, params, a, form, AtomTables::per_call).fill(function, x, p);
}

Eigen::ArrayXd pressure(const WavinessParams& params, double a, const Eigen::Ref<const Eigen::ArrayXd>& x, Form form) {
  Eigen::ArrayXd p(x.size());
  pressure(params, a, x, p, form);
  return p;
}

}  // namespace wavecontact
