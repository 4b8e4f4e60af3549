#include "wavecontact/two_scale.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <mutex>
#include <utility>
#include <stdexcept>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/cos_pi.hpp>
#include <boost/math/special_functions/sin_pi.hpp>
#include <boost/math/tools/roots.hpp>
#include <boost/multiprecision/cpp_int.hpp>

#include "support/parallel.hpp"
#include "kernels/pressure_simd.hpp"
#include "wavecontact/generated/roughness_evaluators.hpp"
#include "support/validate.hpp"
#include "wavecontact/angles.hpp"
#include "wavecontact/contact.hpp"
#include "wavecontact/threads.hpp"
#include "wavecontact/waviness.hpp"

namespace wavecontact {

namespace {

using boost::math::double_constants::pi;

// sum_j k_j z^j of eq. 20 = cos(t) sin(2 n t)/(n sin t) with cos^2 t = z, from the
// Chebyshev form of the k_j (derive/formulas/roughness.hpp); 1 - z is passed separately so that
// small zones keep their digits.
double eq20_sum(int n, double z, double one_minus_z) {
  const double s = std::sqrt(one_minus_z), c = std::sqrt(z);
  if (s == 0) return 2 * c;
  return c * std::sin(2 * n * std::atan2(s, c)) / (n * s);
}

std::mutex registry_mutex;

std::map<int, RoughnessEvaluator>& registry() {
  static std::map<int, RoughnessEvaluator> evaluators = [] {
    std::map<int, RoughnessEvaluator> built_in;
    generated::for_each_roughness_evaluator([&](int n, auto pressure, auto load, auto legendre) {
      built_in[n] = RoughnessEvaluator{n, pressure, load, legendre};
    });
    return built_in;
  }();
  return evaluators;
}

}  // namespace

void validate(const RoughnessParams& r, const char* function) {
  detail::require_scale(function, "H2", r.H2, true);
  if (r.n < 2 || r.n % 2 != 0 || r.n > max_roughness_n) {
    detail::domain_error(function, "n", r.n,
                         "an even integer, 2 <= n <= " + std::to_string(max_roughness_n) + " (wavelength ratio b1/b2)");
  }
}

void register_roughness_evaluator(const RoughnessEvaluator& evaluator) {
  validate(RoughnessParams{0, evaluator.n}, "wavecontact::register_roughness_evaluator");
  for (const auto& [name, missing] :
       {std::pair{"pressure", evaluator.pressure == nullptr}, std::pair{"load", evaluator.load == nullptr},
        std::pair{"legendre", evaluator.legendre == nullptr}}) {
    if (missing) {
      throw std::invalid_argument(std::string("wavecontact::register_roughness_evaluator: ") + name +
                                  " is null for n = " + std::to_string(evaluator.n) + " (pass &roughness_n<N>_" + name +
                                  "<double> of the generated header)");
    }
  }
  const std::lock_guard<std::mutex> lock(registry_mutex);
  registry()[evaluator.n] = evaluator;
}

RoughnessEvaluator roughness_evaluator(int n) {
  constexpr const char* function = "wavecontact::roughness_evaluator";
  validate(RoughnessParams{0, n}, function);
  const std::lock_guard<std::mutex> lock(registry_mutex);
  const auto it = registry().find(n);
  if (it == registry().end()) {
    const std::string N = std::to_string(n);
    detail::domain_error(function, "n", n,
                         "a generated n; generate this one with `wavecontact-derive --n " + N +
                             " --out DIR` or the CMake call wavecontact_generate(TARGET <target> N " + N +
                             "), then register_roughness_evaluator()");
  }
  return it->second;
}

std::vector<int> available_roughness_n() {
  const std::lock_guard<std::mutex> lock(registry_mutex);
  std::vector<int> ns;
  for (const auto& entry : registry()) ns.push_back(entry.first);
  return ns;
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
    : params_(params), a_(a), form_(form), zone_{} {
  constexpr const char* function = "wavecontact::TwoScaleContact";
  const WavinessParams& w = params.waviness;
  validate(w, function);
  validate(params.roughness, function);
  // The roughness solution holds for any zone; the printed eq. 19/20 only up to b1/2.
  if (form == Form::exact) {
    detail::require_half_width(function, a, w.b1, w.b1, false, [&] { return "b1 = " + detail::format(w.b1); });
  } else {
    detail::require_half_width(function, a, w.b1, w.b1 / 2, true,
                               [&] { return "b1/2 = " + detail::format(w.b1 / 2) + " (printed eq. 19/20)"; });
  }
  zone_ = zone_angles(a, w.b1);
  waviness_load_ = wavecontact::load(w, a);  // the printed eq. 13 has the same load (derive/)
  if (form == Form::exact) {
    evaluator_ = roughness_evaluator(params.roughness.n);
    roughness_load_ = evaluator_.load(w.E, params.roughness.H2, zone_.Ca, zone_.Sa);
    legendre_.resize(static_cast<std::size_t>(params.roughness.n));
    evaluator_.legendre(zone_.Ca, legendre_.data());
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
  Eigen::ArrayXd xs(points + 10), p(points + 10);
  for (int i = 0; i < points; ++i) xs[i] = a * i / points;
  for (int k = 1; k <= 10; ++k) xs[points + k - 1] = a * (1 - std::ldexp(1.0, -2 * k));
  wavecontact::pressure(w, a, xs, p, form);
  add_roughness_pressure(xs, p);
  Eigen::Index lowest = 0;
  if (p.minCoeff(&lowest) < 0) most_negative_pressure_ = p[lowest], most_negative_x_ = xs[lowest];
  const double scale = pi / w.b1 * w.E * (w.H1 + params.roughness.H2 * n);
  admissible_ = !(most_negative_pressure_ < -64 * 2.220446049250313e-16 * scale);
  if (form == Form::exact) {  // the printed eq. 19/20 does not solve eq. 5: no gap for it
    const SingleZoneCheck gap = single_zone_check(Surface(params), a);
    if (gap.lowest_gap < 0) lowest_gap_ = gap.lowest_gap, x_of_lowest_gap_ = gap.x_of_lowest_gap;
    admissible_ = admissible_ && !gap.penetrates;
  }
}

double TwoScaleContact::waviness_pressure(double x) const {
  return wavecontact::pressure(params_.waviness, a_, x, form_);
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
    return evaluator_.pressure(w.E, params_.roughness.H2, w.b1, zone_.Ca, zone_.Sa, point.Cx, point.Sx, point.D);
  }
  // Eq. 20: (E* H2 n^2/2) sqrt(alpha^2 - u^2) sum_j k_j z^j, z = cos(a^/2) cos^2(x^/2);
  // 1 - z = 2 sin^2(a^/4) + cos(a^/2) sin^2(x^/2).
  const double Ca = zone_.Ca;
  const double half_cos = std::sqrt((1 + Ca) / 2);
  const double quarter_sin = boost::math::sin_pi(a_ / (4 * w.b1));
  const double z = half_cos * (1 + point.Cx) / 2;
  const double one_minus_z = 2 * quarter_sin * quarter_sin + half_cos * point.Sx / 2;
  const double edge = std::sqrt(2 * point.D / ((1 + point.Cx) * (1 + Ca)));
  return pi / w.b1 * EH2 * n * n / 2 * edge * eq20_sum(n, z, one_minus_z);
}

void TwoScaleContact::add_roughness_pressure(const Eigen::Ref<const Eigen::ArrayXd>& x,
                                             Eigen::Ref<Eigen::ArrayXd> p) const {
  const WavinessParams& w = params_.waviness;
  const bool simd = form_ == Form::exact && a_ <= w.b1 / 2 && detail::simd_roughness_available();
  const int n = params_.roughness.n;
  const detail::RoughnessZone zone{
      w.b1, a_, zone_.Ca, zone_.Sa, pi / w.b1 * w.E * params_.roughness.H2 * n / 2, legendre_.data(), n};
  const double* xs = x.data();
  double* ps = p.data();
  detail::for_each_chunk(static_cast<std::size_t>(x.size()), detail::simd_block, parallel_points,
                         [&](std::size_t begin, std::size_t end) {
                           if (simd) {
                             detail::simd_add_roughness_pressure(zone, xs + begin, ps + begin, end - begin);
                           } else {
                             for (std::size_t i = begin; i < end; ++i) ps[i] += roughness_pressure(xs[i]);
                           }
                         });
}

void TwoScaleContact::roughness_pressure(const Eigen::Ref<const Eigen::ArrayXd>& x,
                                         Eigen::Ref<Eigen::ArrayXd> p) const {
  detail::require_points("wavecontact::TwoScaleContact::roughness_pressure", x, p.size());
  p.setZero();
  add_roughness_pressure(x, p);
}

void TwoScaleContact::require_admissible(const char* function) const {
  if (!admissible_) {
    const std::string why =
        most_negative_pressure_ < 0
            ? "here p = " + detail::format(most_negative_pressure_) + " < 0 at x = " + detail::format(most_negative_x_)
            : "here the surface penetrates by " + detail::format(-lowest_gap_) + " at x = +-" +
                  detail::format(x_of_lowest_gap_);
    detail::domain_error(function, "a", a_,
                         "a zone with p >= 0 on it and gap >= 0 off it; " + why +
                             ": one zone is not the contact (wavecontact::solve_contact)");
  }
}

double TwoScaleContact::pressure(double x) const {
  require_admissible("wavecontact::TwoScaleContact::pressure");
  return waviness_pressure(x) + roughness_pressure(x);
}

void TwoScaleContact::pressure(const Eigen::Ref<const Eigen::ArrayXd>& x, Eigen::Ref<Eigen::ArrayXd> p) const {
  constexpr const char* function = "wavecontact::TwoScaleContact::pressure";
  require_admissible(function);
  detail::require_points(function, x, p.size());
  wavecontact::pressure(params_.waviness, a_, x, p, form_);
  add_roughness_pressure(x, p);
}

double roughness_full_contact_pressure(const TwoScaleParams& params, double x) {
  constexpr const char* function = "wavecontact::roughness_full_contact_pressure";
  validate(params.waviness, function);
  validate(params.roughness, function);
  detail::require_finite(function, "x", x);
  const WavinessParams& w = params.waviness;
  const double n = params.roughness.n;
  const double Cnx = boost::math::cos_pi(n * (reduce_to_period(x, w.b1) / w.b1));
  return generated::roughness_full_contact_pressure(w.E, params.roughness.H2, w.b1, n, Cnx);
}

std::vector<Equilibrium> two_scale_half_widths(const TwoScaleParams& params, double P) {
  constexpr const char* function = "wavecontact::two_scale_half_widths";
  validate(params.waviness, function);
  validate(params.roughness, function);
  detail::require_positive(function, "P", P);
  const double b1 = params.waviness.b1;
  const RoughnessEvaluator evaluator = roughness_evaluator(params.roughness.n);
  auto residual = [&](double a) {
    const ZoneAngles zone = zone_angles(a, b1);
    return load(params.waviness, a) + evaluator.load(params.waviness.E, params.roughness.H2, zone.Ca, zone.Sa) - P;
  };
  // The load of the narrowest zone the half-widths allow (parameters.hpp).
  const double lowest = residual(min_half_width_ratio * b1) + P;
  if (!(P >= lowest)) {
    detail::domain_error(function, "P", P,
                         "P >= " + detail::format(lowest) +
                             ", the load of the narrowest zone a = " + detail::format(min_half_width_ratio) + " b1");
  }
  auto equilibrium = [&](double a, bool rising) {
    return Equilibrium{a, rising, TwoScaleContact(params, a).admissible()};
  };
  // Brackets on (0, b1): the last one stops short of full contact.
  const int intervals = 16 * params.roughness.n + 128;
  std::vector<Equilibrium> roots;
  double lo = 0, f_lo = -P;
  for (int i = 1; i < intervals; ++i) {
    const double hi = b1 * i / intervals, f_hi = residual(hi);
    if (f_hi == 0) {
      roots.push_back(equilibrium(hi, f_lo < 0));
    } else if ((f_lo < 0) != (f_hi < 0) && f_lo != 0) {
      std::uintmax_t iterations = 200;
      const auto [left, right] = boost::math::tools::toms748_solve(
          residual, lo, hi, f_lo, f_hi, boost::math::tools::eps_tolerance<double>(), iterations);
      roots.push_back(equilibrium(left + (right - left) / 2, f_lo < 0));
    }
    lo = hi, f_lo = f_hi;
  }
  return roots;
}

}  // namespace wavecontact
