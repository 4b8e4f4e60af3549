#include <algorithm>
#include <cmath>
#include <string>

#include <boost/math/constants/constants.hpp>

#include "contact/surface_model.hpp"
#include "contact/zone.hpp"
#include "support/validate.hpp"
#include "wavecontact/angles.hpp"
#include "wavecontact/contact.hpp"
#include "wavecontact/generated/waviness_evaluators.hpp"
#include "wavecontact/two_scale.hpp"

namespace wavecontact {

namespace {

using boost::math::double_constants::pi;

// The smallest panel extent in x^ for a surface whose highest harmonic is n.
double resolution(int n) { return pi / std::max(4, n); }

}  // namespace

void validate(const std::vector<Harmonic>& roughness, const char* function) {
  if (roughness.size() > max_harmonics) {
    detail::domain_error(function, "harmonics", static_cast<double>(roughness.size()),
                         "at most " + std::to_string(max_harmonics) + " harmonics");
  }
  for (const Harmonic& h : roughness) {
    if (h.H != 0 && !(std::fabs(h.H) >= min_scale && std::fabs(h.H) <= max_scale)) {
      detail::domain_error(function, "H", h.H,
                           "0 or " + detail::format(min_scale) + " <= |H| <= " + detail::format(max_scale));
    }
    if (h.n < 1 || h.n > max_roughness_n) {
      detail::domain_error(function, "n", h.n, "1 <= n <= " + std::to_string(max_roughness_n));
    }
  }
}

Surface::Surface(const WavinessParams& w, const std::vector<Harmonic>& roughness) : b1_(w.b1), E_(w.E) {
  constexpr const char* function = "wavecontact::Surface";
  validate(w, function);
  validate(roughness, function);
  int highest = 0;
  for (const Harmonic& h : roughness) highest = std::max(highest, h.n);
  height_scale_ = w.H1;
  for (const Harmonic& h : roughness) height_scale_ += std::fabs(h.H);
  auto s = std::make_shared<detail::SurfaceModel>();
  const double H1 = w.H1, m = w.m;
  // Eq. 2 in c = cos x^: the top branch Y(|c|), odd in c; each harmonic H cos(n x^).
  const auto wave = [H1, m](double c) { return std::copysign(generated::waviness_height(H1, m, std::fabs(c)), c); };
  s->height = [=](double x) {
    double y = wave(std::cos(x));
    for (const Harmonic& h : roughness) y += h.H * std::cos(h.n * x);
    return y;
  };
  s->slope = [=](double x) {
    double slope = -std::sin(x) * generated::waviness_height_slope(H1, m, std::fabs(std::cos(x)));
    for (const Harmonic& h : roughness) slope -= h.H * h.n * std::sin(h.n * x);
    return slope;
  };
  // Differences without cancellation: on the waviness, Y(c) - Y(c0) = H1 (m + 1) (c - c0 +
  // m (c |c0| - c0 |c|)) / ((1 + m |c|) (1 + m |c0|)), the second term 0 on one branch and of
  // the sign of c - c0 across; each harmonic's cos(n x) - cos(n x0) = -2 sin(n x0 + u) sin u,
  // u = n (x - x0) / 2, with n x0 as a sum of two doubles (its rounding, by a fused
  // multiply-add, kept apart from u). The slopes in s from the same sines: Y'(|c|) and each
  // harmonic's H n sin(n x) / sin x, sin(n x) = sin(n x0 + 2u).
  s->height_steps = [=](double x0, const double* ds, const double* delta, std::size_t count, double* out,
                        const double* sines, double* slopes) {
    const double c0 = std::cos(x0), denominator_c0 = 1 + m * std::fabs(c0);
    struct Phase {
      double n, H, sine, cosine, rounding;  // sin and cos of n x0 as rounded, n x0 - that
    };
    std::vector<Phase> phases;
    for (const Harmonic& h : roughness) {
      const double n = h.n, p = n * x0;
      phases.push_back({n, h.H, std::sin(p), std::cos(p), std::fma(n, x0, -p)});
    }
    for (std::size_t i = 0; i < count; ++i) {
      const double c = c0 + ds[i];
      double dy = H1 * (m + 1) * (ds[i] + m * (c * std::fabs(c0) - c0 * std::fabs(c))) /
                  ((1 + m * std::fabs(c)) * denominator_c0);
      double dy_ds = slopes ? generated::waviness_height_slope(H1, m, std::fabs(c)) : 0.0;
      for (const Phase& h : phases) {
        const double u = h.n * delta[i] / 2, sin_u = std::sin(u), cos_u = std::cos(u);
        const double sum_sine = h.sine * cos_u + h.cosine * sin_u + h.rounding * (h.cosine * cos_u - h.sine * sin_u);
        dy += h.H * -2 * sum_sine * sin_u;
        if (slopes && sines[i] > 0) {
          const double sum_cosine = h.cosine * cos_u - h.sine * sin_u;
          dy_ds += h.H * h.n * (sum_sine * cos_u + sum_cosine * sin_u) / sines[i];
        }
      }
      out[i] = dy;
      if (slopes) slopes[i] = dy_ds;
    }
  };
  if (m > 0) {
    // x^ = pi/2, c = 0: beyond it the branch Y(c) = -Y_top(-c), so the slopes differ by
    // D'(c) = Y'_top(-c) - Y'_top(c), analytic within 1/m (the branches' poles at c = -+1/m).
    const double E = w.E;
    detail::Kink kink;
    kink.angle = pi / 2, kink.s = 0, kink.radius = 1 / m;
    kink.windows = detail::shared_kink_windows({H1, m, E});
    kink.slope_jump = [=](double c) {
      return E / 2 * (generated::waviness_height_slope(H1, m, -c) - generated::waviness_height_slope(H1, m, c));
    };
    s->kinks.push_back(kink);
  }
  s->resolution = resolution(highest);
  s->E = w.E;
  s->scale = height_scale_;
  detail::locate_top(*s);
  model_ = std::move(s);
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
  const ProfileEvaluator& e = profile.evaluator();
  const std::vector<double>& q = profile.parameter_values();
  auto s = std::make_shared<detail::SurfaceModel>();
  s->height = [e, q](double x) { return e.height(q.data(), std::cos(x)); };
  s->slope = [e, q](double x) { return -std::sin(x) * e.height_slope(q.data(), std::cos(x)); };
  s->height_steps = [e, q](double x0, const double* ds, const double*, std::size_t count, double* out, const double*,
                           double* slopes) {
    const double c0 = std::cos(x0), y0 = e.height(q.data(), c0);
    for (std::size_t i = 0; i < count; ++i) {
      out[i] = e.height(q.data(), c0 + ds[i]) - y0;
      if (slopes) slopes[i] = e.height_slope(q.data(), c0 + ds[i]);
    }
  };
  const double E = profile.params().E;
  if (e.branch.beta > 0) {
    // The branches' slopes from their g(v) = (E/2) Y'(c) sin x^: (E/2) D'(c) = (g_flank - g_top)/sin x^;
    // analytic up to the nearest pole of either branch.
    const auto poles_at = [&q](void (*squares)(const double*, double*), int count) {
      std::vector<double> tau(static_cast<std::size_t>(count)), cs;
      if (count > 0) squares(q.data(), tau.data());
      for (double t : tau) {
        if (std::isfinite(t) && t != -1) cs.push_back((1 - t) / (1 + t));
      }
      return cs;
    };
    std::vector<double> poles = poles_at(e.pole_squares, e.pole_count);
    for (double c : poles_at(e.branch.flank_pole_squares, e.branch.flank_pole_count)) poles.push_back(c);
    detail::Kink kink;
    kink.s = e.branch.cosine, kink.angle = std::acos(kink.s);
    kink.radius = 2;
    for (double c : poles) kink.radius = std::min(kink.radius, std::fabs(c - kink.s));
    const auto branch = e.branch;
    kink.slope_jump = [branch, q, E](double c) {
      const double x = std::acos(std::clamp(c, -1.0, 1.0)), v = std::tan(x / 2);
      return (branch.flank_g(q.data(), E, v) - branch.top_g(q.data(), E, v)) / std::sin(x);
    };
    s->kinks.push_back(kink);
  }
  s->resolution = resolution(e.harmonic);
  s->E = E;
  for (int i = 0; i <= 1024; ++i) height_scale_ = std::max(height_scale_, std::fabs(s->height(pi * i / 1024)));
  s->scale = height_scale_;
  detail::locate_top(*s);
  model_ = std::move(s);
}

double Surface::height(double x) const {
  detail::require_finite("wavecontact::Surface::height", "x", x);
  return model_->height(std::fabs(pi * reduce_to_period(x, b1_) / b1_));
}

}  // namespace wavecontact
