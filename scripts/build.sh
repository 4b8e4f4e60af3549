#!/usr/bin/env bash
# Installs missing Debian packages, then configures and builds wavecontact in build/.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "$(id -u)" -eq 0 ]; then
  scripts/install-deps.sh
else
  echo "build: not root, skipping package installation (run scripts/install-deps.sh as root)"
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build -j"$(nproc)"
