// libFuzzer target: the wavecontact command line. The input is split into arguments at
// newlines; `reproduce` is refused (it writes files). Checks the CLI's contract on every
// input (common/exit_status.hpp): the status is one of the table's; 1, an internal error, is
// a bug and a finding; a failure writes nothing on stdout and exactly one line on stderr; no
// run outlasts the solver's default work budget of 60 s a load (plus the time to stop).
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "app.hpp"
#include "exit_status.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 4096) return 0;
  std::vector<std::string> arguments{"wavecontact"};
  std::string current;
  for (std::size_t i = 0; i < size; ++i) {
    const char c = static_cast<char>(data[i]);
    if (c == '\n') {
      arguments.push_back(current);
      current.clear();
    } else {
      current += c;
    }
  }
  arguments.push_back(current);
  if (arguments.size() > 64) return 0;
  std::vector<const char*> argv;
  for (const auto& a : arguments) argv.push_back(a.c_str());

  namespace status_of = wavecontact::exit_status;
  std::ostringstream out, err;
  const auto start = std::chrono::steady_clock::now();
  const int status = wavecontact::cli::run(static_cast<int>(argv.size()), argv.data(), out, err, false);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // The loads of the run: each has the default budget of 60 s.
  std::size_t loads = 1;
  for (std::size_t i = 1; i + 1 < arguments.size(); ++i) {
    if (arguments[i] == "--P" || arguments[i] == "--pa-over-pstar") {
      loads = std::max<std::size_t>(
          loads, 1 + static_cast<std::size_t>(std::count(arguments[i + 1].begin(), arguments[i + 1].end(), ',')));
    }
  }
  if (seconds > 75.0 * static_cast<double>(loads)) std::abort();  // beyond the default budget
  if (status == status_of::internal_error) std::abort();
  if (status != status_of::success && status != status_of::bad_argument && status != status_of::not_the_contact &&
      status != status_of::beyond_reach && status != status_of::io_error) {
    std::abort();
  }
  if (status != status_of::success) {
    const std::string message = err.str();
    if (!out.str().empty() || message.empty() || message.back() != '\n' || message.find('\n') != message.size() - 1) {
      std::abort();
    }
  }
  return 0;
}
