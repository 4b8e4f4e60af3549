#!/usr/bin/env bash
# The main job: build, then write the seed paper's figures (CSV + PNG) to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
./build/runtime/wavecontact reproduce --out out
