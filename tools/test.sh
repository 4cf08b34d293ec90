#!/usr/bin/env bash
# Quick start, command 2: install what is missing, configure and build everything, run the whole
# test suite through ctest. With --sanitize: a separate build (build-asan/) with
# AddressSanitizer + UndefinedBehaviorSanitizer, the same tests except the RTL side (CIG_WITH_RTL:
# Verilated models are generated, uninstrumented code; their harness runs in the normal build).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/deps.sh
dir=build
flags=(-DCMAKE_BUILD_TYPE=Release)
if [ "${1:-}" = "--sanitize" ]; then
  dir=build-asan
  flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCIG_SANITIZE=ON -DCIG_WITH_RTL=OFF)
fi
cmake -S . -B "$dir" "${flags[@]}" >/dev/null
cmake --build "$dir" -j"$(nproc)"
ctest --test-dir "$dir" -j"$(nproc)" --output-on-failure
