// Domain checks shared by the runtime: every message names the function, the
// parameter, its value and the valid range.
#pragma once

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include <Eigen/Core>

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

// The points of an array evaluator are finite and p has room for one value per point.
inline void require_points(const char* function, const Eigen::Ref<const Eigen::ArrayXd>& x,
                           Eigen::Index p_size) {
  if (p_size != x.size()) {
    domain_error(function, "p.size()", static_cast<double>(p_size),
                 "x.size() = " + std::to_string(x.size()));
  }
  if (!x.allFinite()) {
    for (Eigen::Index i = 0; i < x.size(); ++i) require_finite(function, "x", x[i]);
  }
}

inline std::string format(double value) {
  std::ostringstream os;
  os.precision(17);
  os << value;
  return os.str();
}

}  // namespace wavecontact::detail
