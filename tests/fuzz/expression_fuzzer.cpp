// libFuzzer target: the profile expression and the --param values of wavecontact-derive.
// Input: the expression on the first line, then one NAME or NAME=VALUE a line. Every input
// must be refused with std::invalid_argument (InputRefused or the engine's own refusal)
// or give a well-formed header; any other exception, crash or leak is a finding.
//
// The parse and every bound run on every input. The full derivation runs where it takes
// well under the per-input timeout under the sanitizers (order <= 8, <= 2 parameters);
// beyond that, the tool's time and memory budget (resource_budget.hpp) bounds it.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "expression_input.hpp"
#include "generate.hpp"
#include "symbols.hpp"
#include "user_profile.hpp"

namespace derive = wavecontact::derive;

namespace {

constexpr long fuzzed_order = 8;
constexpr std::size_t fuzzed_parameters = 2;

// The order of the expression, or -1 if it is refused.
long order_of(const derive::ProfileSpec& spec) {
  GiNaC::symtab table;
  table["x"] = derive::sym::x();
  table["Pi"] = GiNaC::Pi;
  for (const auto& p : spec.parameters) table[p.name] = GiNaC::realsymbol(p.name);
  try {
    return derive::checked_order(derive::parse_bounded_expression(spec.expression, table),
                                 derive::sym::x());
  } catch (const derive::InputRefused&) {
    return -1;
  }
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
  const long order = order_of(spec);
  if (order < 0 || order > fuzzed_order || spec.parameters.size() > fuzzed_parameters) return 0;
  try {
    const auto files = derive::generate_profile(spec, "fuzz");
    if (files.size() != 2 || files[0].contents.find("#pragma once") == std::string::npos) {
      std::abort();
    }
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
