// The command line's two refusals, mapped to exit statuses by run() (app.hpp).
#pragma once

#include <cstdio>
#include <stdexcept>
#include <string>

namespace wavecontact::cli {

// A bad or inconsistent argument: exit status 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The single-zone solution has a negative total pressure: exit status 3.
struct InadmissibleError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A double with every digit (%.17g), for the CSV output.
inline std::string all_digits(double value) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

}  // namespace wavecontact::cli
