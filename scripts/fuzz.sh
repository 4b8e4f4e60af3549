#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (AddressSanitizer + UBSan) in build-fuzz/ and runs
# each for SECONDS (default 600), growing a working corpus from the seeds in
# tests/fuzz/corpus/. Fails, keeping the input, if a target crashes, hangs or leaks.
#   scripts/fuzz.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
# CLN and GiNaC keep a few start-up allocations to the end (tests/sanitizers/lsan.supp).
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp"
CC=clang-14 CXX=clang++-14 cmake -S . -B build-fuzz -DWAVECONTACT_FUZZ=ON \
  -DWAVECONTACT_BUILD_TESTS=OFF -DWAVECONTACT_BUILD_BENCH=OFF -DWAVECONTACT_BUILD_PYTHON=OFF \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo > /dev/null
cmake --build build-fuzz -j"$(nproc)" --target cli_fuzzer derive_fuzzer expression_fuzzer
for target in cli derive expression; do
  # A multi-zone contact takes seconds under the sanitizers; two harmonics n = 4 and 64 at
  # m = 6 (build-fuzz found it) take 1.3 s optimised and over 30 s here.
  timeout=120
  [ "$target" = derive ] && timeout=60  # a valid n near 4096 takes ~1 s under the sanitizers
  [ "$target" = expression ] && timeout=60  # derivations up to order 8, two parameters
  work="build-fuzz/work-$target"
  mkdir -p "$work"
  echo "fuzz: ${target}_fuzzer for ${seconds}s"
  if ! "build-fuzz/tests/fuzz/${target}_fuzzer" "$work" "tests/fuzz/corpus/$target" \
      -max_total_time="$seconds" -timeout="$timeout" -rss_limit_mb=4096 -print_final_stats=1 \
      -artifact_prefix="build-fuzz/${target}-" > "build-fuzz/${target}.log" 2>&1; then
    tail -n 40 "build-fuzz/${target}.log" >&2
    echo "fuzz: ${target}_fuzzer failed; the input is in build-fuzz/${target}-*" >&2
    exit 1
  fi
  grep -E "^stat::(number_of_executed_units|peak_rss_mb)" "build-fuzz/${target}.log"
done
