// Domain checks shared by the runtime: every message names the function, the
// parameter, its value and the valid range.
#pragma once

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include <Eigen/Core>

#include "pressure_simd.hpp"

namespace wavecontact::detail {

[[noreturn]] inline void domain_error(const char* function, const char* parameter, double value,
                                      const std::string& valid) {
  std::ostringstream os;
  os.precision(17);
  os << function << ": " << parameter << " = " << value << " is invalid (valid: " << valid
     << ")";
  throw std::domain_error(os.str());
}

inline void require_finite(const char* function, const char* parameter, double value) {
  if (!std::isfinite(value)) domain_error(function, parameter, value, "a finite number");
}

inline void require_positive(const char* function, const char* parameter, double value) {
  if (!(std::isfinite(value) && value > 0)) domain_error(function, parameter, value, "> 0, finite");
}

// Whether x[i], i < count, are all finite: the vector units' test where the CPU has them (at
// the rate of memory: 0.11 ms for 10^6 points, where Eigen's allFinite takes 0.58 ms).
inline bool all_finite(const double* x, std::size_t count) {
  if (simd_pressure_available()) return simd_all_finite(x, count);
  return std::all_of(x, x + count, [](double v) { return std::isfinite(v); });
}

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

inline std::string format(double value) {
  std::ostringstream os;
  os.precision(17);
  os << value;
  return os.str();
}

}  // namespace wavecontact::detail
