#!/usr/bin/env bash
# Installs the Debian 12 packages wavecontact needs, only those that are missing.
# Usage (root): scripts/install-deps.sh
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libginac-dev libcln-dev          # derive/: symbolic engine and exact arithmetic
  libeigen3-dev                    # runtime/: array API
  libsleef-dev                     # runtime/: vectorised sinpi/cospi of the array kernels
  libboost-test-dev libboost-math-dev  # tests/ (Boost.Test), runtime/ (root finding, quadrature)
  libfftw3-dev                     # runtime/: the contact's grid guess; tests/: the oracle
  libcli11-dev                     # the wavecontact CLI
  gnuplot-nox                      # reproduce: PNG plots
  clang-14 libclang-rt-14-dev      # the sanitize presets and fuzzing (libFuzzer)
  clang-format-14 clang-tidy-14    # scripts/check_format.sh (CI), scripts/tidy.sh
  libbenchmark-dev python3-sympy   # bench/ (Google Benchmark; SymPy is the baseline)
  pybind11-dev python3-dev python3-numpy  # python/: the extension module, for Debian's python3
  python3-pytest python3-matplotlib       # tests/python, examples/sweep.py
  python3-distributed                     # wavecontact.map(client=...) on a Dask cluster, its tests
  python3-xarray                          # MapResult.to_xarray(), its tests
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q '^install ok installed$'; then
    missing+=("$p")
  fi
done

if ((${#missing[@]})); then
  echo "install-deps: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "install-deps: all packages present"
fi
