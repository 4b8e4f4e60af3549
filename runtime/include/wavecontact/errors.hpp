// What the library throws besides std::domain_error (an argument outside its valid range,
// whose message names the function, the parameter, its value and the range).
#pragma once

#include <stdexcept>

namespace wavecontact {

// A computation that cannot meet its contract on a valid input: the contact solver's work
// budget spent (SolverOptions::max_seconds), a contact beyond the solver's reach. The message
// says how far it got: the load reached, the zones, the best error estimate.
struct BeyondReach : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace wavecontact
