// libFuzzer target: what wavecontact-derive reads from its user, the --n values (until
// profiles are read, issue 7). Any pair of ints must either be refused with
// std::invalid_argument or yield one well-formed header per n. A valid n near 4096 takes
// about a second under the sanitizers, so scripts/fuzz.sh gives this target 60 s per input.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "emit/file_contents.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<int> ns;
  for (std::size_t i = 0; i + sizeof(std::int16_t) <= size && ns.size() < 2; i += sizeof(std::int16_t)) {
    std::int16_t n;
    std::memcpy(&n, data + i, sizeof n);
    ns.push_back(n);
  }
  try {
    const auto files = wavecontact::derive::generate_roughness(ns);
    if (files.size() != ns.size()) std::abort();
    for (const auto& file : files) {
      if (file.contents.find("#pragma once") == std::string::npos) std::abort();
    }
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
