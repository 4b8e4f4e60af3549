#!/usr/bin/env bash
# Builds the libFuzzer targets in a sanitize preset's tree (clang 14, AddressSanitizer + UBSan)
# and runs each for SECONDS (default 600), growing a working corpus from the seeds in
# tests/fuzz/corpus/. Fails, keeping the input, if a target crashes, hangs or leaks.
#   scripts/fuzz.sh [--preset sanitize|sanitize-full] [SECONDS] [TARGET...]
# TARGET: cli, derive, expression (default: all three, in the sanitize-full preset; the
# sanitize preset, without derive/, builds cli only).
set -euo pipefail
cd "$(dirname "$0")/.."
preset=sanitize-full
if [ "${1:-}" = --preset ]; then
  preset=$2
  shift 2
fi
seconds=${1:-600}
shift || true
targets=("$@")
((${#targets[@]})) || targets=(cli derive expression)
build=build-$preset  # the preset's binaryDir (CMakePresets.json)
# CLN and GiNaC keep a few start-up allocations to the end (tests/sanitizers/lsan.supp).
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp"
cmake --preset "$preset" > /dev/null
cmake --build --preset "$preset" -j"$(nproc)" --target "${targets[@]/%/_fuzzer}"
for target in "${targets[@]}"; do
  # A multi-zone contact takes seconds under the sanitizers; two harmonics n = 4 and 64 at
  # m = 6 (the fuzzer found it) take 1.3 s optimised and over 30 s here.
  timeout=120
  [ "$target" = derive ] && timeout=60  # a valid n near 4096 takes ~1 s under the sanitizers
  [ "$target" = expression ] && timeout=60  # derivations up to order 8, two parameters
  work="$build/fuzz-work-$target"
  mkdir -p "$work"
  echo "fuzz: ${target}_fuzzer for ${seconds}s"
  if ! "$build/tests/fuzz/${target}_fuzzer" "$work" "tests/fuzz/corpus/$target" \
      -max_total_time="$seconds" -timeout="$timeout" -rss_limit_mb=4096 -print_final_stats=1 \
      -artifact_prefix="$build/${target}-" > "$build/fuzz-${target}.log" 2>&1; then
    tail -n 40 "$build/fuzz-${target}.log" >&2
    echo "fuzz: ${target}_fuzzer failed; the input is in $build/${target}-*" >&2
    exit 1
  fi
  grep -E "^stat::(number_of_executed_units|peak_rss_mb)" "$build/fuzz-${target}.log"
done
