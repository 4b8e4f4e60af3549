// An expression as GiNaC prints it, for messages and refusals (not for what is emitted:
// that goes through canonical.hpp).
#pragma once

#include <sstream>
#include <string>

#include <ginac/ginac.h>

namespace wavecontact::derive {

inline std::string printed(const GiNaC::ex& e) {
  std::ostringstream os;
  os << e;
  return os.str();
}

}  // namespace wavecontact::derive
