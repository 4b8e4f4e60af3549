// Domain checks shared by the runtime: every message names the function, the
// parameter, its value and the valid range.
#pragma once

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

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

inline std::string format(double value) {
  std::ostringstream os;
  os.precision(17);
  os << value;
  return os.str();
}

}  // namespace wavecontact::detail
