#include <algorithm>
#include <cmath>
#include <string>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/chebyshev.hpp>

#include "interval_inversion.hpp"
#include "validate.hpp"
#include "wavecontact/angles.hpp"
#include "wavecontact/contact.hpp"
#include "wavecontact/two_scale.hpp"
#include "waviness.hpp"  // generated/

namespace wavecontact {

namespace {

constexpr double pi = boost::math::double_constants::pi;

// The smallest panel extent in x^ for a surface whose highest harmonic is n.
double resolution(int n) { return pi / std::max(4, n); }

// U_(n-1)(c), n >= 1, so that dT_n/ds = n U_(n-1), by the addition formulas of cos(k x^) and
// sin(k x^)/sin x^ over the binary digits of n:
//   T_(a+b) = T_a T_b - (1 - c^2) U_(a-1) U_(b-1),   U_(a+b-1) = U_(a-1) T_b + T_a U_(b-1).
// log2(n) steps instead of the n - 2 of the three-term recurrence, and more accurate (at
// n = 256, 75 eps of n at most against 560 eps, measured on 20001 points).
double chebyshev_u_before(int n, double c) {
  const double w = (1 - c) * (1 + c);
  double T = 1, U = 0, T_power = c, U_power = 1;  // (T_0, U_-1) and (T_1, U_0)
  for (unsigned k = static_cast<unsigned>(n); k != 0; k >>= 1) {
    if (k & 1) {
      const double t = T * T_power - w * U * U_power;
      U = U * T_power + T * U_power, T = t;
    }
    if (k > 1) {
      const double t = T_power * T_power - w * U_power * U_power;
      U_power = 2 * T_power * U_power, T_power = t;
    }
  }
  return U;
}

}  // namespace

Surface::Surface(const WavinessParams& w, const std::vector<Harmonic>& roughness) : b1_(w.b1), E_(w.E) {
  constexpr const char* function = "wavecontact::Surface";
  validate(w, function);
  int highest = 0;
  for (const Harmonic& h : roughness) {
    if (h.H != 0 && !(std::fabs(h.H) >= min_scale && std::fabs(h.H) <= max_scale)) {
      detail::domain_error(function, "H", h.H,
                           "0 or " + detail::format(min_scale) + " <= |H| <= " + detail::format(max_scale));
    }
    if (h.n < 1 || h.n > max_roughness_n) {
      detail::domain_error(function, "n", h.n, "1 <= n <= " + std::to_string(max_roughness_n));
    }
    highest = std::max(highest, h.n);
  }
  height_scale_ = w.H1;
  for (const Harmonic& h : roughness) height_scale_ += std::fabs(h.H);
  auto s = std::make_shared<detail::SurfaceSlope>();
  const double H1 = w.H1, m = w.m;
  // Eq. 2 is odd in s = cos x^ (its |cos| branch): Y(s) = sign(s) Y(|s|), Y'(s) = Y'(|s|);
  // a harmonic is H T_n(s) (Boost.Math's Chebyshev polynomials), with dT_n/ds = n U_(n-1)(s).
  s->height = [=](double c) {
    double y = std::copysign(generated::waviness_height(H1, m, std::fabs(c)), c);
    for (const Harmonic& h : roughness) y += h.H * boost::math::chebyshev_t(static_cast<unsigned>(h.n), c);
    return y;
  };
  s->slope = [=](double c) {
    double slope = generated::waviness_height_slope(H1, m, std::fabs(c));
    for (const Harmonic& h : roughness) slope += h.H * h.n * chebyshev_u_before(h.n, c);
    return slope;
  };
  if (m > 0) {
    s->kinks = {0};  // x = b1/2, where eq. 2 changes branch
    // Each branch continued across the kink has its pole at cos x^ = -+1/m (MATH.md fact 8).
    s->singularities = [m](double lo, double /*hi*/) {
      return std::vector<std::complex<double>>{lo >= 0 ? -1 / m : 1 / m};
    };
  }
  s->resolution = resolution(highest);
  s->E = w.E;
  slope_ = std::move(s);
}

Surface::Surface(const TwoScaleParams& params)
    : Surface((validate(params.roughness, "wavecontact::Surface"), params.waviness),
              {{params.roughness.H2, params.roughness.n}}) {}

Surface::Surface(const Profile& profile) : b1_(profile.params().b1), E_(profile.params().E) {
  if (profile.reach() < profile.params().b1) {
    detail::domain_error("wavecontact::Surface", "x", profile.reach(),
                         "a profile without a pole on the period; " + profile.params().name +
                             " has one at this x, where it is unbounded");
  }
  const ProfileEvaluator e = profile.evaluator();
  const std::vector<double> q = profile.parameter_values();
  auto s = std::make_shared<detail::SurfaceSlope>();
  s->height = [e, q](double c) { return e.height(q.data(), c); };
  for (int i = 0; i <= 1024; ++i) height_scale_ = std::max(height_scale_, std::fabs(s->height(std::cos(pi * i / 1024))));
  s->slope = [e, q](double c) { return e.height_slope(q.data(), c); };
  // The poles tau = tan^2(x^/2) off the period are at s = (1 - tau)/(1 + tau). A profile built
  // with abs() has a kink at its branch point, and each piece the poles of its own branch's
  // formula continued (those of eq. 2 at cos x^ = -+1/m, on the other piece for m > 1).
  const auto poles_at = [&q](void (*squares)(const double*, double*), int count) {
    std::vector<double> tau(static_cast<std::size_t>(count));
    if (count > 0) squares(q.data(), tau.data());
    std::vector<std::complex<double>> poles;
    for (double t : tau) {
      if (std::isfinite(t) && t != -1) poles.emplace_back((1 - t) / (1 + t));
    }
    return poles;
  };
  const std::vector<std::complex<double>> top = poles_at(e.pole_squares, e.pole_count);
  if (e.branch.beta > 0) {
    const double cosine = e.branch.cosine;
    const std::vector<std::complex<double>> flank = poles_at(e.branch.flank_pole_squares, e.branch.flank_pole_count);
    s->kinks = {cosine};
    s->singularities = [top, flank, cosine](double lo, double) { return lo >= cosine ? top : flank; };
  } else {
    s->singularities = [top](double, double) { return top; };
  }
  s->resolution = resolution(e.harmonic);
  s->E = profile.params().E;
  slope_ = std::move(s);
}

double Surface::height(double x) const {
  detail::require_finite("wavecontact::Surface::height", "x", x);
  return slope_->height(std::cos(pi * reduce_to_period(x, b1_) / b1_));
}

}  // namespace wavecontact
