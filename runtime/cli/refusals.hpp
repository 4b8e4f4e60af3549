// The command line's refusals, mapped to the exit statuses of common/exit_status.hpp by
// run() (app.hpp), and the format of its numbers.
#pragma once

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace wavecontact::cli {

// A bad or inconsistent argument: exit status 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The single-zone solution has a negative total pressure or penetrates: exit status 3.
struct InadmissibleError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A result that misses its tolerance: exit status 4, as wavecontact::BeyondReach.
struct NotWithinTolerance : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Output that cannot be written, a helper program that fails: exit status 5.
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A double with every digit (%.17g), for the CSV output. A result that is not finite is a
// bug (the domain checks refuse what would overflow): std::logic_error, exit status 1.
inline std::string all_digits(double value) {
  if (!std::isfinite(value)) throw std::logic_error("a result is not finite");
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

}  // namespace wavecontact::cli
