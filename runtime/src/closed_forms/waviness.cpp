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

#include "closed_forms/periodic_regime.hpp"
#include "support/validate.hpp"
#include "wavecontact/angles.hpp"
#include "wavecontact/generated/waviness_evaluators.hpp"

namespace wavecontact {

using boost::math::double_constants::pi;

double pa_over_pstar(const WavinessParams& params, double a, Form form) {
  constexpr const char* function = "wavecontact::pa_over_pstar";
  validate(params, function);
  detail::require_waviness_half_width(function, params, a, form, true);
  const ZoneAngles zone = zone_angles(a, params.b1);
  if (form == Form::exact && a > params.b1 / 2) return detail::load_beyond_half(1.0, 1.0, params.m, zone) / pi;
  return generated::waviness_pa_over_pstar(params.m, zone.Ca, zone.Sa);
}

double load(const WavinessParams& params, double a, Form form) {
  constexpr const char* function = "wavecontact::load";
  validate(params, function);
  detail::require_waviness_half_width(function, params, a, form, true);
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
  detail::require_waviness_half_width(function, params, a, Form::exact, true);
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
  detail::require_waviness_half_width(function, params, a, Form::exact, true);
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
