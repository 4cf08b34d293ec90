#!/usr/bin/env bash
# Quick start, command 2: install what is missing, configure and build everything, run the whole
# test suite through ctest. With --sanitize: a separate build (build-asan/) with
# AddressSanitizer + UndefinedBehaviorSanitizer, the same tests except the RTL side (CIG_WITH_RTL:
# Verilated models are generated, uninstrumented code; their harness runs in the normal build).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/deps.sh
dir=build
flags=(-DCMAKE_BUILD_TYPE=Release -DCIG_BUILD_TESTS=ON -DCIG_WITH_RTL=ON)
if [ "${1:-}" = "--sanitize" ]; then
  dir=build-asan
  flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCIG_SANITIZE=ON -DCIG_BUILD_TESTS=ON -DCIG_WITH_RTL=OFF)
fi
tools/configure.sh "$dir" "${flags[@]}"
cmake --build "$dir" -j"$(nproc)"
ctest --test-dir "$dir" -j"$(nproc)" --output-on-failure
