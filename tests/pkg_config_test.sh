#!/usr/bin/env bash
# Builds a program against the installed runtime with pkg-config only, and runs it.
#   pkg_config_test.sh PREFIX WORKDIR CXX "EXTRA FLAGS"
set -euo pipefail
prefix=$1 work=$2 cxx=$3 extra=${4:-}
mkdir -p "$work"
cat > "$work/main.cpp" <<'CPP'
#include <cstdio>
#include <wavecontact/waviness.hpp>
int main() {
  const wavecontact::WavinessParams p{1.0, 3.141592653589793, 2.0, 1.0};
  const double P = wavecontact::load(p, 0.45 * 3.141592653589793);
  std::printf("%.16g\n", P);
  return P > 1.5256934306558 && P < 1.5256934306559 ? 0 : 1;  // docs/mathematics.md: 1.525693430655888
}
CPP
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
# shellcheck disable=SC2046,SC2086
"$cxx" -std=c++17 $extra "$work/main.cpp" -o "$work/main" $(pkg-config --cflags --libs wavecontact)
"$work/main"
