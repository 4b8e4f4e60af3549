#include "wavecontact/shape_design.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/minima.hpp>

#include "support/validate.hpp"
#include "wavecontact/stability.hpp"
#include "wavecontact/waviness.hpp"

namespace wavecontact {

namespace {

using boost::math::double_constants::pi;
constexpr int scan_points = 256, start_shapes = 24;

// Normalised units: H1 = E* = 1, b1 = pi; pa/p* = P/pi.
WavinessParams normalised(double m) { return {1.0, pi, m, 1.0}; }

// The stable, admissible zone carrying P, or 0 if there is none.
double stable_half_width(const WavinessParams& params, double P) {
  if (P <= load(params, params.b1 / 2)) return single_asperity_half_width(params, P);
  for (const Equilibrium& e : LoadCurve(params).equilibria(P)) {
    if (e.stable && e.admissible) return e.a;
  }
  return 0;
}

}  // namespace

PressureUniformity pressure_uniformity(double m, double ratio) {
  constexpr const char* function = "wavecontact::pressure_uniformity";
  if (!(std::isfinite(m) && m >= 0)) detail::domain_error(function, "m", m, ">= 0, finite");
  detail::require_positive(function, "pa/p*", ratio);
  const WavinessParams params = normalised(m);
  const double P = ratio * pi;
  const double a = stable_half_width(params, P);
  if (a == 0) {
    detail::domain_error(function, "pa/p*", ratio,
                         "a load that one stable, admissible contact zone carries at m = " + detail::format(m));
  }
  // p is even in x: the maximum over [0, a), located on a grid, then refined.
  const auto p = [&](double x) { return pressure(params, a, x); };
  int best = 0;
  double best_p = p(0);
  for (int i = 1; i < scan_points; ++i) {
    const double value = p(a * i / scan_points);
    if (value > best_p) best = i, best_p = value;
  }
  const double lo = a * std::max(best - 1, 0) / scan_points, hi = a * (best + 1) / scan_points;
  const auto [x_max, minus_p] = boost::math::tools::brent_find_minima([&](double x) { return -p(x); }, lo, hi, 40);
  const double maximum = std::max(best_p, -minus_p);
  const double x_of_max = -minus_p > best_p ? x_max : a * best / scan_points;
  return {m, a / params.b1, maximum / (P / (2 * a)), x_of_max / a};
}

PressureUniformity most_uniform_shape(double ratio, double m_max) {
  constexpr const char* function = "wavecontact::most_uniform_shape";
  detail::require_positive(function, "pa/p*", ratio);
  detail::require_positive(function, "m_max", m_max);
  const double t_max = std::log1p(m_max);
  const auto objective = [&](double t) {
    try {
      return pressure_uniformity(std::expm1(t), ratio).max_over_mean;
    } catch (const std::domain_error&) {
      return std::numeric_limits<double>::infinity();
    }
  };
  int best = 0;
  double best_value = objective(0);
  for (int i = 1; i <= start_shapes; ++i) {
    const double value = objective(t_max * i / start_shapes);
    if (value < best_value) best = i, best_value = value;
  }
  if (!std::isfinite(best_value)) {
    detail::domain_error(function, "pa/p*", ratio,
                         "a load that one stable, admissible contact zone carries for some "
                         "0 <= m <= " +
                             detail::format(m_max));
  }
  const double lo = t_max * std::max(best - 1, 0) / start_shapes;
  const double hi = t_max * std::min(best + 1, start_shapes) / start_shapes;
  const auto [t, value] = boost::math::tools::brent_find_minima(objective, lo, hi, 30);
  return pressure_uniformity(std::expm1(value < best_value ? t : t_max * best / start_shapes), ratio);
}

}  // namespace wavecontact
