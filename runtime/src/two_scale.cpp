#include "wavecontact/two_scale.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/sin_pi.hpp>
#include <boost/math/tools/roots.hpp>
#include <boost/multiprecision/cpp_int.hpp>

#include "validate.hpp"
#include "wavecontact/angles.hpp"
#include "wavecontact/waviness.hpp"

namespace wavecontact {

namespace {

constexpr double pi = boost::math::double_constants::pi;

// sum_j k_j z^j of eq. 20 = cos(t) sin(2 n t)/(n sin t) with cos^2 t = z, from the
// Chebyshev form of the k_j (derive/roughness.hpp); 1 - z is passed separately so that
// small zones keep their digits.
double eq20_sum(int n, double z, double one_minus_z) {
  const double s = std::sqrt(one_minus_z), c = std::sqrt(z);
  if (s == 0) return 2 * c;
  return c * std::sin(2 * n * std::atan2(s, c)) / (n * s);
}

// P_0..P_n at y by the three-term recurrence (stable upward for |y| <= 1).
std::vector<double> legendre_values(int n, double y) {
  std::vector<double> P(n + 1);
  P[0] = 1;
  if (n >= 1) P[1] = y;
  for (int k = 1; k < n; ++k) P[k + 1] = ((2 * k + 1) * y * P[k] - k * P[k - 1]) / (k + 1);
  return P;
}

// P_{n-1}(y) - P_n(y) for y = 1 - t without cancellation near y = 1:
// D_{k+1} = (k D_k + (2k+1) t P_k)/(k+1), D_1 = t.
double legendre_step_difference(int n, double t, const std::vector<double>& P) {
  double D = 0;
  for (int k = 0; k < n; ++k) D = (k * D + (2 * k + 1) * t * P[k]) / (k + 1);
  return D;
}

double roughness_load_exact(const TwoScaleParams& p, const ZoneAngles& zone,
                            const std::vector<double>& legendre) {
  const auto& r = p.roughness;
  return pi / 2 * p.waviness.E * r.H2 * r.n * legendre_step_difference(r.n, zone.Sa, legendre);
}

}  // namespace

void validate(const RoughnessParams& r, const char* function) {
  if (!(std::isfinite(r.H2) && r.H2 >= 0)) detail::domain_error(function, "H2", r.H2, ">= 0, finite");
  if (r.n < 2 || r.n % 2 != 0) {
    detail::domain_error(function, "n", r.n, "an even integer >= 2 (wavelength ratio b1/b2)");
  }
}

std::vector<std::string> expansion_coefficients(int n) {
  using boost::multiprecision::cpp_int;
  validate(RoughnessParams{0, n}, "wavecontact::expansion_coefficients");
  std::vector<std::string> k;
  for (int j = 1; j <= n; ++j) {
    // C(n-1+j, n-j) 2^(2j-1) / n, in lowest terms.
    cpp_int numerator = 1;
    for (int i = 1; i <= n - j; ++i) numerator = numerator * (2 * j - 1 + i) / i;  // C(2j-1+i, i)
    numerator <<= 2 * j - 1;
    cpp_int denominator = n;
    const cpp_int common = boost::multiprecision::gcd(numerator, denominator);
    numerator /= common;
    denominator /= common;
    if ((n - j) % 2 != 0) numerator = -numerator;
    k.push_back(numerator.str() + (denominator == 1 ? "" : "/" + denominator.str()));
  }
  return k;
}

TwoScaleContact::TwoScaleContact(const TwoScaleParams& params, double a, Form form)
    : params_(params), a_(a), form_(form) {
  constexpr const char* function = "wavecontact::TwoScaleContact";
  const WavinessParams& w = params.waviness;
  validate(w, function);
  validate(params.roughness, function);
  if (!(std::isfinite(a) && a > 0 && a <= w.b1 / 2)) {
    detail::domain_error(function, "a", a, "0 < a <= b1/2 = " + detail::format(w.b1 / 2));
  }
  const ZoneAngles zone = zone_angles(a, w.b1);
  legendre_ = legendre_values(params.roughness.n, zone.Ca);
  waviness_load_ = wavecontact::load(w, a);  // the printed eq. 13 has the same load (derive/)
  if (form == Form::exact) {
    roughness_load_ = roughness_load_exact(params, zone, legendre_);
  } else {
    // Eq. 20 integrated over the zone: Gauss-Chebyshev (second kind) in u = alpha cos(phi),
    // geometric convergence for the smooth eq. 20 factor.
    const int n = params.roughness.n, nodes = 4 * n + 64;
    const double alpha = std::tan(pi * a / (2 * w.b1));
    const double root = std::sqrt(1 + alpha * alpha);
    double sum = 0;
    for (int k = 0; k < nodes; ++k) {
      const double phi = pi * (k + 0.5) / nodes, u = alpha * std::cos(phi), s = std::sin(phi);
      const double q = root * (1 + u * u);  // 1/z
      const double one_minus_z = (alpha * alpha / (root + 1) * (1 + u * u) + u * u) / q;
      sum += s * s * eq20_sum(n, 1 / q, one_minus_z) / (1 + u * u);
    }
    const double scale = w.E * params.roughness.H2 * n * n / 2.0;
    roughness_load_ = 2 * scale * alpha * alpha * pi * sum / nodes;
  }

  // Admissibility scan of the total pressure.
  const int n = params.roughness.n, points = 16 * n + 64;
  std::vector<double> xs;
  for (int i = 0; i < points; ++i) xs.push_back(a * i / points);
  for (int k = 1; k <= 10; ++k) xs.push_back(a * (1 - std::ldexp(1.0, -2 * k)));
  const double scale = pi / w.b1 * w.E * (w.H1 + params.roughness.H2 * n);
  for (double x : xs) {
    const double p = waviness_pressure(x) + roughness_pressure(x);
    if (p < most_negative_pressure_) most_negative_pressure_ = p, most_negative_x_ = x;
  }
  admissible_ = !(most_negative_pressure_ < -64 * 2.220446049250313e-16 * scale);
}

double TwoScaleContact::waviness_pressure(double x) const {
  return wavecontact::pressure(params_.waviness, a_, x, form_);
}

double TwoScaleContact::roughness_sum(double Cx, double Sx) const {
  // Clenshaw for sum_j c_j V_j(Cx), c_j = P_{n-1-j}(Ca), V_{j+1} = 2 Cx V_j - V_{j-1},
  // V_0 = 1, V_1 = 2 Cx - 1: b_j = c_j + 2 Cx b_{j+1} - b_{j+2}, sum = b_0 - b_1.
  // Near Cx = 1 the plain recurrence amplifies rounding like n^2; Reinsch's modification
  // carries d_j = b_j - b_{j+1} with 2 (Cx - 1) = -2 Sx taken from the atom Sx (no
  // cancellation): d_j = c_j - 2 Sx b_{j+1} + d_{j+1}, b_j = d_j + b_{j+1}, sum = d_0.
  const int n = params_.roughness.n;
  if (Cx > 0.5) {
    double b = 0, d = 0;
    for (int j = n - 1; j >= 0; --j) {
      d = legendre_[n - 1 - j] - 2 * Sx * b + d;
      b = d + b;
    }
    return d;
  }
  double b1 = 0, b2 = 0;
  for (int j = n - 1; j >= 0; --j) {
    const double b0 = legendre_[n - 1 - j] + 2 * Cx * b1 - b2;
    b2 = b1;
    b1 = b0;
  }
  return b1 - b2;
}

double TwoScaleContact::roughness_pressure(double x) const {
  detail::require_finite("wavecontact::TwoScaleContact::roughness_pressure", "x", x);
  const WavinessParams& w = params_.waviness;
  const double r = std::fabs(reduce_to_period(x, w.b1));
  if (r >= a_) return 0;
  const PointAngles point = point_angles(r, a_, w.b1);
  const int n = params_.roughness.n;
  const double EH2 = w.E * params_.roughness.H2;
  if (form_ == Form::exact) {
    return pi / w.b1 * EH2 * n / 2 * std::sqrt(point.D * (1 + point.Cx)) *
           roughness_sum(point.Cx, point.Sx);
  }
  // Eq. 20: (E* H2 n^2/2) sqrt(alpha^2 - u^2) sum_j k_j z^j, z = cos(a^/2) cos^2(x^/2);
  // 1 - z = 2 sin^2(a^/4) + cos(a^/2) sin^2(x^/2).
  const double Ca = zone_angles(a_, w.b1).Ca;
  const double half_cos = std::sqrt((1 + Ca) / 2);
  const double quarter_sin = boost::math::sin_pi(a_ / (4 * w.b1));
  const double z = half_cos * (1 + point.Cx) / 2;
  const double one_minus_z = 2 * quarter_sin * quarter_sin + half_cos * point.Sx / 2;
  const double edge = std::sqrt(2 * point.D / ((1 + point.Cx) * (1 + Ca)));
  return pi / w.b1 * EH2 * n * n / 2 * edge * eq20_sum(n, z, one_minus_z);
}

double TwoScaleContact::pressure(double x) const {
  if (!admissible_) {
    detail::domain_error("wavecontact::TwoScaleContact::pressure", "a", a_,
                         "a zone where the total pressure is >= 0; here p = " +
                             detail::format(most_negative_pressure_) + " < 0 at x = " +
                             detail::format(most_negative_x_) +
                             ": the single-zone (continuous contact) solution is not physical");
  }
  return waviness_pressure(x) + roughness_pressure(x);
}

std::vector<double> two_scale_half_widths(const TwoScaleParams& params, double P) {
  constexpr const char* function = "wavecontact::two_scale_half_widths";
  validate(params.waviness, function);
  validate(params.roughness, function);
  detail::require_positive(function, "P", P);
  const double b1 = params.waviness.b1;
  auto residual = [&](double a) {
    const ZoneAngles zone = zone_angles(a, b1);
    const auto legendre = legendre_values(params.roughness.n, zone.Ca);
    return load(params.waviness, a) + roughness_load_exact(params, zone, legendre) - P;
  };
  const int intervals = 8 * params.roughness.n + 64;
  std::vector<double> roots;
  double lo = 0, f_lo = -P;
  for (int i = 1; i <= intervals; ++i) {
    const double hi = b1 / 2 * i / intervals, f_hi = residual(hi);
    if (f_hi == 0) {
      roots.push_back(hi);
    } else if ((f_lo < 0) != (f_hi < 0) && f_lo != 0) {
      std::uintmax_t iterations = 200;
      const auto [left, right] = boost::math::tools::toms748_solve(
          residual, lo, hi, f_lo, f_hi, boost::math::tools::eps_tolerance<double>(), iterations);
      roots.push_back(left + (right - left) / 2);
    }
    lo = hi, f_lo = f_hi;
  }
  return roots;
}

}  // namespace wavecontact
