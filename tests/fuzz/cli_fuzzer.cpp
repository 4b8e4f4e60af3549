// libFuzzer target: the wavecontact command line. The input is split into arguments at
// newlines; `reproduce` is refused (it writes files). Checks the CLI's contract on every
// input: a failure writes nothing on stdout, and a bad argument (status 2) or a negative
// pressure (status 3) prints exactly one line on stderr.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "app.hpp"

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

  std::ostringstream out, err;
  const int status =
      wavecontact::cli::run(static_cast<int>(argv.size()), argv.data(), out, err, false);
  if (status != 0 && !out.str().empty()) std::abort();
  if (status == 2 || status == 3) {
    const std::string message = err.str();
    if (message.empty() || message.back() != '\n' ||
        message.find('\n') != message.size() - 1) {
      std::abort();
    }
  }
  return 0;
}
