#include "wavecontact/stability.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/sin_pi.hpp>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>

#include "closed_forms/periodic_regime.hpp"
#include "support/validate.hpp"
#include "wavecontact/contact.hpp"
#include "wavecontact/waviness.hpp"

namespace wavecontact {

namespace {

using boost::math::double_constants::pi;
constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr int slope_samples = 256;

// A root of f in [lo, hi], where f(lo) and f(hi) differ in sign (TOMS 748 to full precision).
template <typename F>
double bracketed_root(const F& f, double lo, double hi, double f_lo, double f_hi) {
  if (f_lo == 0) return lo;
  if (f_hi == 0) return hi;
  std::uintmax_t iterations = 200;
  const auto [left, right] =
      boost::math::tools::toms748_solve(f, lo, hi, f_lo, f_hi, boost::math::tools::eps_tolerance<double>(), iterations);
  return left + (right - left) / 2;
}

// The lowest of the pressures p[i] at the points xs[i]; below -64 eps scale counts as negative.
Admissibility lowest_pressure(const std::vector<double>& xs, const std::vector<double>& p, double scale) {
  Admissibility result{true, 0, 0, 0, 0};
  for (std::size_t i = 0; i < xs.size(); ++i) {
    if (p[i] < result.most_negative_pressure) {
      result.most_negative_pressure = p[i];
      result.most_negative_x = xs[i];
    }
  }
  result.admissible = !(result.most_negative_pressure < -64 * eps * scale);
  return result;
}

// The pressure's verdict with the gap off the zone added.
Admissibility with_gap(Admissibility result, const Surface& surface, double a) {
  const SingleZoneCheck check = single_zone_check(surface, a);
  result.lowest_gap = std::min(0.0, check.lowest_gap);
  result.x_of_lowest_gap = check.lowest_gap < 0 ? check.x_of_lowest_gap : 0;
  result.admissible = result.admissible && !check.penetrates;
  return result;
}

// 128 evenly spaced points of [0, a) and 10 approaching the edge.
std::vector<double> zone_points(double a) {
  std::vector<double> xs;
  for (int i = 0; i < 128; ++i) xs.push_back(a * i / 128);
  for (int k = 1; k <= 10; ++k) xs.push_back(a * (1 - std::ldexp(1.0, -2 * k)));
  return xs;
}

// The one equilibrium of a curve (P > 0 checked by the caller before building the curve),
// or a domain error naming every candidate.
double unique_half_width(const char* function, const LoadCurve& curve, double P) {
  const std::vector<Equilibrium> solutions = curve.equilibria(P);
  if (solutions.empty()) {
    detail::domain_error(function, "P", P,
                         "0 < P <= " + detail::format(curve.maximum_load()) +
                             ", the largest load of one contact zone per period (beyond it the "
                             "contact is full)");
  }
  if (solutions.size() > 1) {
    std::string list;
    for (const Equilibrium& e : solutions) {
      list += (list.empty() ? "" : ", ") + detail::format(e.a) + (e.stable ? " (stable)" : " (unstable)");
    }
    detail::domain_error(function, "P", P,
                         "a load carried by one half-width only; this one is carried by a = " + list +
                             ": use wavecontact::LoadCurve::equilibria()");
  }
  return solutions.front().a;
}

}  // namespace

Admissibility admissibility(const WavinessParams& params, double a) {
  constexpr const char* function = "wavecontact::admissibility";
  validate(params, function);
  detail::require_half_width(function, a, params.b1, params.b1, false,
                             [&] { return "b1 = " + detail::format(params.b1); });
  std::vector<double> xs = zone_points(a);
  const double kink = params.b1 / 2;
  if (a > kink) {
    for (int i = 0; i < 32; ++i) xs.push_back(kink + (a - kink) * i / 32);
  }
  std::vector<double> p;
  for (double x : xs) p.push_back(pressure(params, a, x));
  return with_gap(lowest_pressure(xs, p, pstar(params)), Surface(params), a);
}

Admissibility admissibility(const Profile& profile, double a) {
  const std::vector<double> xs = zone_points(a);
  std::vector<double> p;
  double scale = 0;
  for (double x : xs) {
    p.push_back(profile.pressure(a, x));
    scale = std::max(scale, std::fabs(p.back()));
  }
  const Admissibility by_pressure = lowest_pressure(xs, p, scale);
  return profile.reach() < profile.params().b1 ? by_pressure : with_gap(by_pressure, Surface(profile), a);
}

LoadCurve::LoadCurve(const WavinessParams& params)
    : load_([params](double a) { return load(params, a); }),
      admissible_([params](double a) { return admissibility(params, a).admissible; }),
      b1_(params.b1),
      end_(params.b1) {
  validate(params, "wavecontact::LoadCurve");
  // dP/da = (pi/b1) sin(pi a/b1) F(a) has the sign of the slope factor F, r = a/b1 in (0, 1];
  // F does not vanish at r = 1 as dP/da does, through the sine.
  const WavinessParams unit{1.0, 1.0, params.m, 1.0};
  locate_turning_points([unit](double r) { return detail::load_slope_factor(unit, r); });
}

LoadCurve::LoadCurve(const Profile& profile)
    : load_([profile](double a) { return profile.load(a); }),
      admissible_([profile](double a) { return admissibility(profile, a).admissible; }),
      b1_(profile.params().b1),
      // Short of a pole, where the load grows without bound.
      end_(profile.reach() < profile.params().b1 ? profile.reach() * (1 - 1e-9) : profile.reach()) {
  // dP/da = (pi/b1) sin(pi a/b1) F(a) vanishes at a = b1 through the sine: step back from it.
  locate_turning_points(
      [&profile, end = end_](double r) { return profile.load_slope(r < 1 ? r * end : end * (1 - 1e-9)); });
}

void LoadCurve::locate_turning_points(const std::function<double(double)>& slope) {
  std::vector<double> r(slope_samples + 1), f(slope_samples + 1);
  for (int i = 0; i <= slope_samples; ++i) {
    r[i] = static_cast<double>(i) / slope_samples;
    f[i] = i == 0 ? 0 : slope(r[i]);
  }
  std::vector<double> roots;
  for (int i = 1; i < slope_samples; ++i) {
    if ((f[i] < 0) != (f[i + 1] < 0)) {
      roots.push_back(bracketed_root(slope, r[i], r[i + 1], f[i], f[i + 1]));
    } else if (f[i] > 0 && i + 1 < slope_samples && f[i] <= f[i - 1] && f[i] <= f[i + 1]) {
      // A positive local minimum on the grid may hide a short dip below zero.
      const auto [r_min, f_min] = boost::math::tools::brent_find_minima(slope, r[i - 1], r[i + 1], 52);
      if (f_min < 0) {
        roots.push_back(bracketed_root(slope, r[i - 1], r_min, f[i - 1], f_min));
        roots.push_back(bracketed_root(slope, r_min, r[i + 1], f_min, f[i + 1]));
      }
    }
  }
  std::sort(roots.begin(), roots.end());
  turning_points_.push_back(0);
  for (double root : roots) turning_points_.push_back(root * end_);
  turning_points_.push_back(end_);
  for (double a : turning_points_) turning_loads_.push_back(a > 0 ? load_(a) : 0);
  for (std::size_t i = 1; i < turning_points_.size(); ++i) {
    if (turning_loads_[i] < turning_loads_[i - 1]) {
      unstable_.push_back({turning_points_[i - 1], turning_points_[i]});
    }
  }
  maximum_load_ = *std::max_element(turning_loads_.begin(), turning_loads_.end());
  full_contact_load_ = turning_loads_.back();
}

std::vector<Equilibrium> LoadCurve::equilibria(double P) const {
  constexpr const char* function = "wavecontact::LoadCurve::equilibria";
  // The load of the narrowest zone the half-widths allow (parameters.hpp).
  const double lowest = load_(min_half_width_ratio * b1_);
  if (!(std::isfinite(P) && P >= lowest)) {
    detail::domain_error(function, "P", P,
                         "P >= " + detail::format(lowest) +
                             ", the load of the narrowest zone a = " + detail::format(min_half_width_ratio) + " b1");
  }
  std::vector<Equilibrium> result;
  for (std::size_t i = 1; i < turning_points_.size(); ++i) {
    const double lo = turning_points_[i - 1], hi = turning_points_[i];
    const double f_lo = turning_loads_[i - 1] - P, f_hi = turning_loads_[i] - P;
    if ((f_lo > 0 && f_hi > 0) || (f_lo < 0 && f_hi < 0) || f_lo == f_hi) continue;
    const double a = bracketed_root([&](double x) { return load_(x) - P; }, lo, hi, f_lo, f_hi);
    if (a <= 0 || a >= end_) continue;
    if (!result.empty() && result.back().a == a) continue;  // P at a turning point
    result.push_back({a, f_hi > f_lo, admissible_(a)});
  }
  return result;
}

double contact_half_width(const WavinessParams& params, double P) {
  constexpr const char* function = "wavecontact::contact_half_width";
  validate(params, function);
  detail::require_positive(function, "P", P);
  return unique_half_width(function, LoadCurve(params), P);
}

double contact_half_width(const Profile& profile, double P) {
  constexpr const char* function = "wavecontact::contact_half_width";
  detail::require_positive(function, "P", P);
  return unique_half_width(function, LoadCurve(profile), P);
}

double contact_half_width_for_pa_over_pstar(const WavinessParams& params, double ratio) {
  constexpr const char* function = "wavecontact::contact_half_width_for_pa_over_pstar";
  validate(params, function);
  detail::require_positive(function, "pa/p*", ratio);
  return contact_half_width(params, ratio * pi * params.E * params.H1);
}

}  // namespace wavecontact
