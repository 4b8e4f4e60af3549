#!/usr/bin/env bash
# What CI runs (the README's test command), about 12 minutes on 2 cores:
# 1. the normal build (scripts/build.sh, which installs what is missing), the format of the
#    C++ sources (scripts/check_format.sh), and the build's whole suite;
# 2. the runtime, the CLI and their tests built with clang's AddressSanitizer and
#    UndefinedBehaviorSanitizer (CMakePresets.json, preset sanitize: -O1 with line tables),
#    the tests labelled long left out; then the CLI's fuzz target for 10 s;
# 3. the benchmarks in a smoke mode (a few iterations; never timed assertions), without the
#    cases that take seconds each (scripts/bench.sh runs them).
# With --full, step 2 takes the sanitize-full preset instead: derive/ too, every test, and
# the three fuzz targets. Run it after a change to derive/ or the contact solver.
set -euo pipefail
cd "$(dirname "$0")/.."
sanitize=sanitize fuzz_targets=(cli)
if [ "${1:-}" = --full ]; then
  sanitize=sanitize-full fuzz_targets=(cli derive expression)
elif (($#)); then
  echo "usage: scripts/test.sh [--full]" >&2
  exit 2
fi
scripts/build.sh
scripts/check_format.sh
ctest --preset default -j"$(nproc)"
cmake --preset "$sanitize"
cmake --build --preset "$sanitize" -j"$(nproc)"
ctest --preset "$sanitize" -j"$(nproc)"
scripts/fuzz.sh --preset "$sanitize" 10 "${fuzz_targets[@]}"
scripts/bench.sh --benchmark_min_time=0.001 --benchmark_filter=-'many_zones|curve_200/0'
