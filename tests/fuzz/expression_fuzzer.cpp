// libFuzzer target: the profile expression and the --param values of wavecontact-derive.
// Input: the expression on the first line, then one NAME or NAME=VALUE a line. Every input
// must be refused with std::invalid_argument (InputRefused or the engine's own refusal)
// or give a well-formed header; any other exception, crash or leak is a finding.
//
// The parse and every bound run on every input. The full derivation runs where it takes
// well under the per-input timeout under the sanitizers (<= 2 parameters, order <= 8, or 4
// with abs(), or a cosine sum of order <= 64, which splits off whole: derive/profile/harmonic_part.hpp);
// beyond that, the tool's time and memory budget (resource_budget.hpp) bounds it.
//
// Every emitted header must compile (issue 28: profiles without parameters emitted
// "f(, Scalar* out)"): the first derived input and every 16th after it are written out and
// compiled with -Wall -Wextra -Werror -pedantic; a failure is a finding.
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/symbols.hpp"
#include "emit/file_contents.hpp"
#include "formulas/user_profile.hpp"
#include "profile/expression_input.hpp"

extern char** environ;

namespace derive = wavecontact::derive;

namespace {

constexpr long fuzzed_order = 8;
// With abs() the derivation adds both branches, the sub-interval moments and full contact:
// H*cos(x)^4*(5*cos(x)-3)*abs(5*cos(x)-3), order 6, takes 2 s optimised and 84 s under the
// sanitizers (the fuzzer found it), beyond the 60 s per input.
constexpr long fuzzed_branched_order = 4;
constexpr long fuzzed_cosine_sum_order = 64;
constexpr std::size_t fuzzed_parameters = 2;

// Whether the expression passes its bounds and derives quickly enough to fuzz.
bool derivable(const derive::ProfileSpec& spec) {
  GiNaC::symtab table;
  table["x"] = derive::sym::x();
  table["Pi"] = GiNaC::Pi;
  for (const auto& p : spec.parameters) table[p.name] = GiNaC::realsymbol(p.name);
  try {
    const derive::ProfileOrder order =
        derive::checked_order(derive::parse_bounded_expression(spec.expression, table), derive::sym::x());
    if (spec.parameters.size() > fuzzed_parameters) return false;
    const long limit = spec.expression.find("abs") == std::string::npos ? fuzzed_order : fuzzed_branched_order;
    if (order.denominator == 0 && limit == fuzzed_order) return order.numerator <= fuzzed_cosine_sum_order;
    return order.numerator <= limit && order.denominator <= limit;
  } catch (const derive::InputRefused&) {
    return false;
  }
}

// Compiles the emitted header under the strict flags; aborts if it does not.
void require_compiles(const std::string& header) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("wavecontact_fuzz_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "profile_fuzz.hpp") << header;
  std::ofstream(dir / "main.cpp") << "#include \"profile_fuzz.hpp\"\n";
  std::vector<std::string> words{WAVECONTACT_FUZZ_CXX,
                                 "-std=c++17",
                                 "-fsyntax-only",
                                 "-Wall",
                                 "-Wextra",
                                 "-Werror",
                                 "-pedantic",
                                 "-I" WAVECONTACT_RUNTIME_INCLUDE,
                                 "-I" WAVECONTACT_GENERATED_DIR,
                                 "-I" + dir.string(),
                                 (dir / "main.cpp").string()};
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) std::abort();
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) std::abort();  // the header is in dir
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  derive::ProfileSpec spec{"fuzz", "", {}};
  std::getline(lines, spec.expression);
  try {
    for (std::string line; std::getline(lines, line) && spec.parameters.size() < 10;) {
      spec.parameters.push_back(derive::parse_parameter(line));
    }
  } catch (const derive::InputRefused&) {
    return 0;
  }
  if (!derivable(spec)) return 0;
  try {
    const auto files = derive::generate_profile(spec, "fuzz");
    if (files.size() != 2 || files[0].contents.find("#pragma once") == std::string::npos) {
      std::abort();
    }
    static int derived = 0;
    if (derived++ % 16 == 0) require_compiles(files[0].contents);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
