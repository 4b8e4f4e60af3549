#!/usr/bin/env bash
# Build, then run the whole test suite: the normal build, then the same suite built with
# AddressSanitizer and UndefinedBehaviorSanitizer (CMakePresets.json, at -O1 with line tables:
# the build takes less and the reports keep their lines), the tests on every core, then the fuzz
# targets for a few seconds each (scripts/fuzz.sh), then the benchmarks in a smoke mode
# (a few iterations; never timed assertions), without the many-zone contacts beside boundary
# elements, whose grids take minutes to choose (scripts/bench.sh runs them).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
ctest --preset default -j"$(nproc)"
cmake --preset sanitize
cmake --build --preset sanitize -j"$(nproc)"
ctest --preset sanitize -j"$(nproc)"
scripts/fuzz.sh 10
scripts/bench.sh --benchmark_min_time=0.001 --benchmark_filter=-many_zones
