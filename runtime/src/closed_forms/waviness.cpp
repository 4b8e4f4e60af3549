#include "wavecontact/waviness.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/sin_pi.hpp>
#include <boost/math/tools/roots.hpp>

#include "support/parallel.hpp"
#include "closed_forms/periodic_regime.hpp"
#include "support/validate.hpp"
#include "wavecontact/angles.hpp"
#include "wavecontact/isa.hpp"
#include "wavecontact/threads.hpp"
#include "wavecontact/generated/waviness_evaluators.hpp"
#include "kernels/pressure_simd.hpp"

namespace wavecontact {

namespace {

using boost::math::double_constants::pi;

// One zone per period: 0 < a < b1 (a = b1 allowed where `full_contact_allowed`, the limit
// of full contact). The printed formulas beyond b1/2 are the analytic branch of eq. 2,
// defined while 1 + m cos(pi a/b1) > 0.
void require_half_width(const char* function, const WavinessParams& p, double a, Form form,
                        bool full_contact_allowed = false) {
  detail::require_half_width(function, a, p.b1, p.b1, full_contact_allowed,
                             "b1 = " + detail::format(p.b1) + " (one contact zone per period)");
  if (form == Form::paper && a > p.b1 / 2 && !(1 + p.m * zone_angles(a, p.b1).Ca > 0)) {
    detail::domain_error(function, "a", a,
                         "for the printed eq. 13/14, 1 + m cos(pi a/b1) > 0: beyond a = b1/2 they "
                         "continue the top branch of eq. 2, which has a pole at cos(pi x/b1) = -1/m");
  }
}

double pressure_at(const WavinessParams& p, double a, const ZoneAngles& zone, double x, Form form) {
  const double r = std::fabs(reduce_to_period(x, p.b1));
  if (r >= a) return 0;
  const PointAngles point = point_angles(r, a, p.b1);
  if (form == Form::exact && a > p.b1 / 2) return detail::pressure_beyond_half(p, zone, point);
  return form == Form::exact
             ? generated::waviness_pressure_exact(p.E, p.H1, p.b1, p.m, zone.Ca, zone.Sa, point.Cx, point.Sx, point.D)
             : generated::waviness_pressure_paper(p.E, p.H1, p.b1, p.m, zone.Ca, zone.Sa, point.Cx, point.Sx, point.D);
}

// Beyond b1/2 the exact form is the closed forms with J_{j,l} atoms, with the zone's atoms kept
// (detail::BeyondHalfZone; no SIMD kernel); the printed one continues its closed form.
bool beyond_half_exact(const WavinessParams& p, double a, Form form) { return form == Form::exact && a > p.b1 / 2; }

}  // namespace

double pressure(const WavinessParams& params, double a, double x, Form form) {
  constexpr const char* function = "wavecontact::pressure";
  validate(params, function);
  require_half_width(function, params, a, form);
  detail::require_finite(function, "x", x);
  return pressure_at(params, a, zone_angles(a, params.b1), x, form);
}

void pressure(const WavinessParams& params, double a, const Eigen::Ref<const Eigen::ArrayXd>& x,
              Eigen::Ref<Eigen::ArrayXd> p, Form form) {
  constexpr const char* function = "wavecontact::pressure";
  validate(params, function);
  require_half_width(function, params, a, form);
  detail::require_same_size(function, x, p.size());
  const ZoneAngles zone = zone_angles(a, params.b1);
  const auto count = static_cast<std::size_t>(x.size());
  const double* xs = x.data();
  double* ps = p.data();
  if (beyond_half_exact(params, a, form)) {
    detail::require_finite_points(function, x);
    detail::BeyondHalfZone(params, zone).pressures(a, params.b1, xs, ps, count, parallel_points_costly);
    return;
  }
  const bool simd = detail::simd_pressure_available();
  const detail::WavinessZone simd_zone{params.E, params.H1, params.b1, params.m, a, zone.Ca, zone.Sa};
  // The points are checked in the threads, before any is computed.
  const bool finite = detail::for_each_chunk(
      count, detail::simd_block, parallel_points,
      [xs](std::size_t begin, std::size_t end) { return detail::all_finite(xs + begin, end - begin); },
      [&](std::size_t begin, std::size_t end) {
        if (simd) {
          detail::simd_pressure(simd_zone, form, xs + begin, ps + begin, end - begin);
        } else {
          for (std::size_t i = begin; i < end; ++i) ps[i] = pressure_at(params, a, zone, xs[i], form);
        }
      });
  if (!finite) detail::require_finite_points(function, x);
}

Eigen::ArrayXd pressure(const WavinessParams& params, double a, const Eigen::Ref<const Eigen::ArrayXd>& x, Form form) {
  Eigen::ArrayXd p(x.size());
  pressure(params, a, x, p, form);
  return p;
}

namespace detail {

bool simd_pressure_available() { return array_kernel_isa() != Isa::scalar; }

void simd_pressure(const WavinessZone& zone, Form form, const double* x, double* p, std::size_t count) {
  if (array_kernel_isa() == Isa::avx512) return avx512::simd_pressure(zone, form, x, p, count);
  avx2::simd_pressure(zone, form, x, p, count);
}

void simd_point_angles(double b1, double a, const double* x, std::size_t count, PointAngles* angles,
                       unsigned char* inside) {
  if (array_kernel_isa() == Isa::avx512) return avx512::simd_point_angles(b1, a, x, count, angles, inside);
  avx2::simd_point_angles(b1, a, x, count, angles, inside);
}

void simd_add_roughness_pressure(const RoughnessZone& zone, const double* x, double* p, std::size_t count) {
  if (array_kernel_isa() == Isa::avx512) return avx512::simd_add_roughness_pressure(zone, x, p, count);
  avx2::simd_add_roughness_pressure(zone, x, p, count);
}

bool simd_all_finite(const double* x, std::size_t count) {
  if (array_kernel_isa() == Isa::avx512) return avx512::simd_all_finite(x, count);
  return avx2::simd_all_finite(x, count);
}

bool all_finite(const double* x, std::size_t count) {
  if (simd_pressure_available()) return simd_all_finite(x, count);
  return std::all_of(x, x + count, [](double v) { return std::isfinite(v); });
}

}  // namespace detail

double pa_over_pstar(const WavinessParams& params, double a, Form form) {
  constexpr const char* function = "wavecontact::pa_over_pstar";
  validate(params, function);
  require_half_width(function, params, a, form, true);
  const ZoneAngles zone = zone_angles(a, params.b1);
  if (form == Form::exact && a > params.b1 / 2) return detail::load_beyond_half(1.0, 1.0, params.m, zone) / pi;
  return generated::waviness_pa_over_pstar(params.m, zone.Ca, zone.Sa);
}

double load(const WavinessParams& params, double a, Form form) {
  constexpr const char* function = "wavecontact::load";
  validate(params, function);
  require_half_width(function, params, a, form, true);
  const ZoneAngles zone = zone_angles(a, params.b1);
  // Beyond b1/2 the exact pressure reaches the |cos| branch (the printed form continues its
  // own closed form, whose load is waviness_load).
  if (form == Form::exact && a > params.b1 / 2) return detail::load_beyond_half(params.E, params.H1, params.m, zone);
  return generated::waviness_load(params.E, params.H1, params.m, zone.Ca, zone.Sa);
}

namespace detail {

// Beyond b1/2: the form that holds the digits, by the top piece's argument z (waviness_evaluators.hpp):
// for the load the near-half form where z >= 1 (within 3 eps of the 40-digit value either
// way); for its slope the form by parts where z >= 0, the derivative of the load's terms
// elsewhere (tests/accuracy_test.cpp).
// The closed forms beyond b1/2 carry powers of m up to m^4, which overflow for m near 1e77.
// There m enters as m (-Ca) with -Ca >= 1e-16 (a at least an ulp above b1/2), so beyond
// m = 1e60 the results change by less than 1e-40: they are evaluated at m = 1e60.
constexpr double flat_punch_m = 1e60;

double load_beyond_half(double E, double H1, double m_given, const ZoneAngles& zone) {
  const double m = std::min(m_given, flat_punch_m);
  return generated::waviness_top_piece_argument(m, zone.Ca, zone.Sa) >= 1
             ? generated::waviness_load_near_half(E, H1, m, zone.Ca, zone.Sa)
             : generated::waviness_load_beyond_half(E, H1, m, zone.Ca, zone.Sa);
}

double load_slope_factor(const WavinessParams& params, double a) {
  const ZoneAngles zone = zone_angles(a, params.b1);
  const double E = params.E, H1 = params.H1, Ca = zone.Ca, Sa = zone.Sa;
  if (a <= params.b1 / 2) return generated::waviness_load_slope_factor(E, H1, params.m, Ca, Sa);
  const double m = std::min(params.m, flat_punch_m);
  return generated::waviness_top_piece_argument(m, Ca, Sa) >= 0
             ? generated::waviness_load_slope_factor_by_parts(E, H1, m, Ca, Sa)
             : generated::waviness_load_slope_factor_beyond_half(E, H1, m, Ca, Sa);
}

}  // namespace detail

double load_slope(const WavinessParams& params, double a) {
  constexpr const char* function = "wavecontact::load_slope";
  validate(params, function);
  require_half_width(function, params, a, Form::exact, true);
  // sin(pi a/b1) = sin(pi (b1 - a)/b1), b1 - a exact beyond b1/2: no digits lost as a -> b1.
  const double sine = boost::math::sin_pi((a > params.b1 / 2 ? params.b1 - a : a) / params.b1);
  return pi / params.b1 * sine * detail::load_slope_factor(params, a);
}

double pstar(const WavinessParams& params) {
  validate(params, "wavecontact::pstar");
  return pi * params.E * params.H1 / (2 * params.b1);
}

double mean_pressure(const WavinessParams& params, double a) { return load(params, a) / (2 * params.b1); }

double contact_fraction(const WavinessParams& params, double a) {
  constexpr const char* function = "wavecontact::contact_fraction";
  validate(params, function);
  require_half_width(function, params, a, Form::exact, true);
  return a / params.b1;
}

double single_asperity_half_width(const WavinessParams& params, double P) {
  constexpr const char* function = "wavecontact::single_asperity_half_width";
  validate(params, function);
  // pa/p* is increasing in Sa = 1 - cos(pi a/b1), from 0 at a = 0 to its value at Sa = 1
  // (a = b1/2), with the derivative dpa/p*/dSa = load_slope_factor/(pi E* H1) (generated):
  // safeguarded Newton in Sa, no trigonometry inside the loop.
  const double m = params.m;
  const auto ratio_at = [m](double Sa) { return generated::waviness_pa_over_pstar(m, 1 - Sa, Sa); };
  const double ratio = P / (pi * params.E * params.H1), maximum = ratio_at(1);
  // A few ulp of slack, so that the value computed at a = b1/2 maps back to b1/2.
  const double slack = 8 * std::numeric_limits<double>::epsilon() * maximum;
  if (!(std::isfinite(ratio) && ratio > 0 && ratio <= maximum + slack)) {
    detail::domain_error(function, "P", P,
                         "0 < P <= " + detail::format(maximum * pi * params.E * params.H1) + " (the load at a = b1/2)");
  }
  if (ratio >= maximum) return params.b1 / 2;
  const auto residual = [&](double Sa) {
    const double Ca = 1 - Sa;
    return std::make_pair(ratio_at(Sa) - ratio, generated::waviness_load_slope_factor(1.0, 1.0, m, Ca, Sa) / pi);
  };
  // Start from the small-zone limit pa/p* ~ Sa/(2 (1 + m)) of the closed form.
  const double start = std::min(2 * (1 + m) * ratio, 1.0);
  std::uintmax_t iterations = 100;
  const double Sa = boost::math::tools::newton_raphson_iterate(residual, start, 0.0, 1.0,
                                                               std::numeric_limits<double>::digits, iterations);
  // a^ = 2 asin(sqrt(Sa/2)) keeps its digits for small zones, where acos(1 - Sa) would not.
  return params.b1 * 2 * std::asin(std::sqrt(Sa / 2)) / pi;
}

double wave_curve(const WavinessParams& params, double x) {
  constexpr const char* function = "wavecontact::wave_curve";
  validate(params, function);
  detail::require_finite(function, "x", x);
  const double c = std::cos(pi * x / params.b1);
  return params.H1 * (params.m + 1) * c / (params.m * std::fabs(c) + 1);  // eq. 2
}

}  // namespace wavecontact
