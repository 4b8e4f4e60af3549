// WAVECONTACT_TRACE=1 in the environment: the solver's steps on stderr (every Newton
// iteration, every change of zones: where a solve went wrong, and why).
#pragma once

#include "configuration.hpp"

namespace wavecontact::detail {

bool tracing();
void trace_configuration(const char* what, double P, const Configuration& c, const char* outcome);

}  // namespace wavecontact::detail
