#!/usr/bin/env bash
# Quick start, command 1: install what is missing (only what `cig` needs), configure and build the
# product binary `cig` (Release), and render the default scene (scenes/airfield.json) to out/: one
# PNG per channel, a panorama, report.json. Extra arguments go to `cig render` (e.g. --frames 0:119).
# A fresh build directory is configured without the tests and the RTL (no GoogleTest, SystemC or
# Verilator needed); tools/test.sh later turns them on in the same directory, reusing what is built.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/deps.sh render
if [ -f build/CMakeCache.txt ]; then
  tools/configure.sh build
else
  tools/configure.sh build -DCMAKE_BUILD_TYPE=Release -DCIG_BUILD_TESTS=OFF -DCIG_WITH_RTL=OFF
fi
cmake --build build -j"$(nproc)" --target cig
if [ $# -eq 0 ]; then set -- --frame 0; fi
build/bin/cig render scenes/airfield.json --out out "$@"
