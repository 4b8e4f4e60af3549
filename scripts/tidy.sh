#!/usr/bin/env bash
# Runs clang-tidy 14 with the checks of .clang-tidy on every tracked C++ source that build/
# compiles (its compile_commands.json). Fails on the first finding.
#   scripts/tidy.sh [FILE-REGEX]
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_EXPORT_COMPILE_COMMANDS=ON > /dev/null
filter=${1:-'/(runtime|derive|common|tests|bench|python)/.*\.cpp$'}
run-clang-tidy-14 -p build -quiet -j "$(nproc)" "$filter"
