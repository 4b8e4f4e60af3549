#include "trace.hpp"

#include <cstdio>
#include <cstdlib>

namespace wavecontact::detail {

bool tracing() {
  static const bool on = [] {
    const char* value = std::getenv("WAVECONTACT_TRACE");
    return value != nullptr && *value != '\0' && *value != '0';
  }();
  return on;
}

void trace_configuration(const char* what, double P, const Configuration& c, const char* outcome) {
  if (!tracing()) return;
  std::fprintf(stderr, "wavecontact trace: %s P = %.9g: %s, %zu zone%s:", what, P, outcome, c.zones.size(),
               c.zones.size() == 1 ? "" : "s");
  for (const ZoneUnknowns& z : c.zones) {
    std::fprintf(stderr, " [%.6g, %.6g]/%zu", z.geometry.a, z.geometry.b, z.d.size());
    if (z.kink_window > 0) std::fprintf(stderr, " (kink window %.3g)", z.kink_window);
  }
  std::fprintf(stderr, "\n");
}

}  // namespace wavecontact::detail
