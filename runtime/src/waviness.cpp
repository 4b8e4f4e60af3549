#include "wavecontact/waviness.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/roots.hpp>

#include "validate.hpp"
#include "wavecontact/angles.hpp"
#include "waviness.hpp"  // generated/

namespace wavecontact {

namespace {

constexpr double pi = boost::math::double_constants::pi;

// The closed forms hold while the zone stays on the top half of each asperity.
void require_half_width(const char* function, const WavinessParams& p, double a) {
  if (!(std::isfinite(a) && a > 0 && a <= p.b1 / 2)) {
    detail::domain_error(function, "a", a,
                         "0 < a <= b1/2 = " + detail::format(p.b1 / 2) +
                             " (closed form for one zone per period on the asperity's top half)");
  }
}

double pressure_at(const WavinessParams& p, double a, const ZoneAngles& zone, double x,
                   Form form) {
  const double r = std::fabs(reduce_to_period(x, p.b1));
  if (r >= a) return 0;
  const PointAngles point = point_angles(r, a, p.b1);
  return form == Form::exact
             ? generated::waviness_pressure_exact(p.E, p.H1, p.b1, p.m, zone.Ca, zone.Sa,
                                                  point.Cx, point.Sx, point.D)
             : generated::waviness_pressure_paper(p.E, p.H1, p.b1, p.m, zone.Ca, zone.Sa,
                                                  point.Cx, point.Sx, point.D);
}

}  // namespace

double pressure(const WavinessParams& params, double a, double x, Form form) {
  constexpr const char* function = "wavecontact::pressure";
  validate(params, function);
  require_half_width(function, params, a);
  detail::require_finite(function, "x", x);
  return pressure_at(params, a, zone_angles(a, params.b1), x, form);
}

Eigen::ArrayXd pressure(const WavinessParams& params, double a,
                        const Eigen::Ref<const Eigen::ArrayXd>& x, Form form) {
  constexpr const char* function = "wavecontact::pressure";
  validate(params, function);
  require_half_width(function, params, a);
  const ZoneAngles zone = zone_angles(a, params.b1);
  Eigen::ArrayXd p(x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    detail::require_finite(function, "x", x[i]);
    p[i] = pressure_at(params, a, zone, x[i], form);
  }
  return p;
}

double pa_over_pstar(const WavinessParams& params, double a) {
  constexpr const char* function = "wavecontact::pa_over_pstar";
  validate(params, function);
  require_half_width(function, params, a);
  const ZoneAngles zone = zone_angles(a, params.b1);
  return generated::waviness_pa_over_pstar(params.m, zone.Ca, zone.Sa);
}

double load(const WavinessParams& params, double a) {
  constexpr const char* function = "wavecontact::load";
  validate(params, function);
  require_half_width(function, params, a);
  const ZoneAngles zone = zone_angles(a, params.b1);
  return generated::waviness_load(params.E, params.H1, params.m, zone.Ca, zone.Sa);
}

double pstar(const WavinessParams& params) {
  validate(params, "wavecontact::pstar");
  return pi * params.E * params.H1 / (2 * params.b1);
}

double mean_pressure(const WavinessParams& params, double a) {
  return load(params, a) / (2 * params.b1);
}

double contact_fraction(const WavinessParams& params, double a) {
  constexpr const char* function = "wavecontact::contact_fraction";
  validate(params, function);
  require_half_width(function, params, a);
  return a / params.b1;
}

double contact_half_width_for_pa_over_pstar(const WavinessParams& params, double ratio) {
  constexpr const char* function = "wavecontact::contact_half_width_for_pa_over_pstar";
  validate(params, function);
  // pa/p* grows monotonically from 0 at a = 0 to its maximum at a = b1/2; r = a/b1.
  auto ratio_at = [&](double r) {
    const ZoneAngles zone = zone_angles(r, 1.0);
    return generated::waviness_pa_over_pstar(params.m, zone.Ca, zone.Sa);
  };
  const double maximum = ratio_at(0.5);
  // A few ulp of slack, so that the value computed at a = b1/2 maps back to b1/2.
  const double slack = 8 * std::numeric_limits<double>::epsilon() * maximum;
  if (!(std::isfinite(ratio) && ratio > 0 && ratio <= maximum + slack)) {
    detail::domain_error(function, "pa/p*", ratio,
                         "0 < pa/p* <= " + detail::format(maximum) + " (the value at a = b1/2)");
  }
  if (ratio >= maximum) return params.b1 / 2;
  std::uintmax_t iterations = 200;
  const auto [lo, hi] = boost::math::tools::toms748_solve(
      [&](double r) { return ratio_at(r) - ratio; }, 0.0, 0.5, -ratio, maximum - ratio,
      boost::math::tools::eps_tolerance<double>(), iterations);
  return params.b1 * (lo + (hi - lo) / 2);
}

double contact_half_width(const WavinessParams& params, double P) {
  constexpr const char* function = "wavecontact::contact_half_width";
  validate(params, function);
  detail::require_positive(function, "P", P);
  const double maximum = load(params, params.b1 / 2);
  if (P > maximum * (1 + 8 * std::numeric_limits<double>::epsilon())) {
    detail::domain_error(function, "P", P,
                         "0 < P <= " + detail::format(maximum) + " (the load at a = b1/2)");
  }
  return contact_half_width_for_pa_over_pstar(params, P / (pi * params.E * params.H1));
}

double wave_curve(const WavinessParams& params, double x) {
  constexpr const char* function = "wavecontact::wave_curve";
  validate(params, function);
  detail::require_finite(function, "x", x);
  const double c = std::cos(pi * x / params.b1);
  return params.H1 * (params.m + 1) * c / (params.m * std::fabs(c) + 1);  // eq. 2
}

}  // namespace wavecontact
