// A Boost.Test global fixture for the tests that ctest runs once per array-kernel path
// (WAVECONTACT_ISA, wavecontact/isa.hpp): it names the path in the log, and skips the run
// (exit status 77, ctest's SKIP_RETURN_CODE) when this CPU lacks the path asked for, rather
// than test another path under its name.
#pragma once

#include <cstdlib>
#include <iostream>
#include <string>

#include <boost/test/unit_test.hpp>

#include "wavecontact/isa.hpp"

struct IsaUnderTest {
  IsaUnderTest() {
    const char* requested = std::getenv("WAVECONTACT_ISA");
    const char* running = wavecontact::isa_name(wavecontact::array_kernel_isa());
    if (requested != nullptr && *requested != '\0' && std::string(requested) != running) {
      std::cout << "skipped: this CPU has no " << requested << " path (best: " << running << ")\n";
      std::exit(77);
    }
    std::cout << "array kernels: " << running << "\n";
  }
};
BOOST_TEST_GLOBAL_FIXTURE(IsaUnderTest);
