// Domain checks shared by the runtime: every message names the function, the
// parameter, its value and the valid range.
#pragma once

#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include <Eigen/Core>

#include "wavecontact/angles.hpp"
#include "wavecontact/parameters.hpp"

namespace wavecontact::detail {

// The shortest decimal that reads back as `value` (1e-20, not 9.9999999999999995e-21; 10, not
// 1e+01), whatever the locale.
inline std::string format(double value) {
  char text[32];
  const std::to_chars_result end = std::to_chars(text, text + sizeof text, value);
  return std::string(text, end.ptr);
}

[[noreturn]] inline void domain_error(const char* function, const char* parameter, double value,
                                      const std::string& valid) {
  throw std::domain_error(std::string(function) + ": " + parameter + " = " + format(value) +
                          " is invalid (valid: " + valid + ")");
}

inline void require_finite(const char* function, const char* parameter, double value) {
  if (!std::isfinite(value)) domain_error(function, parameter, value, "a finite number");
}

inline void require_positive(const char* function, const char* parameter, double value) {
  if (!(std::isfinite(value) && value > 0)) domain_error(function, parameter, value, "> 0, finite");
}

// A dimensional parameter within [min_scale, max_scale] (parameters.hpp), or also 0 where
// `zero_allowed` (a roughness height).
inline void require_scale(const char* function, const char* parameter, double value, bool zero_allowed = false) {
  if (zero_allowed && value == 0) return;
  if (!(std::isfinite(value) && value >= min_scale && value <= max_scale)) {
    domain_error(
        function, parameter, value,
        std::string(zero_allowed ? "0 or " : "") + format(min_scale) + " <= " + parameter + " <= " + format(max_scale));
  }
}

// A zone's half-width: min_half_width_ratio b1 <= a < upper (<= upper where `closed`);
// `upper_text()` says what the upper bound is (called only to refuse: a scalar evaluation
// does not pay for the text).
template <class UpperText>
void require_half_width(const char* function, double a, double b1, double upper, bool closed,
                        const UpperText& upper_text) {
  const double lowest = min_half_width_ratio * b1;
  if (!(std::isfinite(a) && a >= lowest && (a < upper || (closed && a == upper)))) {
    domain_error(
        function, "a", a,
        format(lowest) + " = " + format(min_half_width_ratio) + " b1 <= a " + (closed ? "<= " : "< ") + upper_text());
  }
}

// One zone of the wave curve per period: 0 < a < b1 (a = b1 allowed where
// `full_contact_allowed`, the limit of full contact). The printed formulas beyond b1/2 are the
// analytic branch of eq. 2, defined while 1 + m cos(pi a/b1) > 0.
inline void require_waviness_half_width(const char* function, const WavinessParams& p, double a, Form form,
                                        bool full_contact_allowed = false) {
  require_half_width(function, a, p.b1, p.b1, full_contact_allowed,
                     [&] { return "b1 = " + format(p.b1) + " (one contact zone per period)"; });
  if (form == Form::paper && a > p.b1 / 2 && !(1 + p.m * zone_angles(a, p.b1).Ca > 0)) {
    domain_error(function, "a", a,
                 "for the printed eq. 13/14, 1 + m cos(pi a/b1) > 0: beyond a = b1/2 they "
                 "continue the top branch of eq. 2, which has a pole at cos(pi x/b1) = -1/m");
  }
}

// Whether x[i], i < count, are all finite: the vector units' test where the CPU has them (at
// the rate of memory: 0.11 ms for 10^6 points, where Eigen's allFinite takes 0.58 ms);
// defined beside the dispatch to those units (waviness.cpp).
bool all_finite(const double* x, std::size_t count);

// p has room for one value per point of x.
inline void require_same_size(const char* function, const Eigen::Ref<const Eigen::ArrayXd>& x, Eigen::Index p_size) {
  if (p_size != x.size()) {
    domain_error(function, "p.size()", static_cast<double>(p_size), "x.size() = " + std::to_string(x.size()));
  }
}

// Throws for the first point of x that is not finite, if any.
inline void require_finite_points(const char* function, const Eigen::Ref<const Eigen::ArrayXd>& x) {
  for (Eigen::Index i = 0; i < x.size(); ++i) require_finite(function, "x", x[i]);
}

// The points of an array evaluator are finite and p has room for one value per point (the
// fast kernels check in their threads instead: for_each_chunk with a check).
inline void require_points(const char* function, const Eigen::Ref<const Eigen::ArrayXd>& x, Eigen::Index p_size) {
  require_same_size(function, x, p_size);
  if (!all_finite(x.data(), static_cast<std::size_t>(x.size()))) require_finite_points(function, x);
}

}  // namespace wavecontact::detail
