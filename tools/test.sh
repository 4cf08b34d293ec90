#!/usr/bin/env bash
# Quick start, command 2: install what is missing, configure and build everything, run the whole
# test suite through ctest. With --sanitize: a separate clang build (build-asan/) with
# AddressSanitizer + UndefinedBehaviorSanitizer, the same tests except the RTL side (CIG_WITH_RTL:
# Verilated models are generated, uninstrumented code; their harness runs in the normal build),
# plus a bounded run of every libFuzzer target (verif/fuzz; tools/fuzz.sh runs them longer).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/deps.sh
# The real database the flightgear.* tests import (Iceland, from Debian's flightgear-data-base; cached
# in ~/.cache/cig/flightgear after the first run, about 1.5 minutes).
tools/fetch_flightgear.sh w030n60
dir=build
flags=(-DCMAKE_BUILD_TYPE=Release -DCIG_BUILD_TESTS=ON -DCIG_WITH_RTL=ON)
if [ "${1:-}" = "--sanitize" ]; then
  # clang: libFuzzer is clang's, and the fuzz targets (verif/fuzz) run here, a minute each.
  dir=build-asan
  export CXX=clang++
  flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCIG_SANITIZE=ON -DCIG_FUZZ=ON -DCIG_BUILD_TESTS=ON -DCIG_WITH_RTL=OFF)
fi
tools/configure.sh "$dir" "${flags[@]}"
cmake --build "$dir" -j"$(nproc)"
ctest --test-dir "$dir" -j"$(nproc)" --output-on-failure
