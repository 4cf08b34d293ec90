#!/usr/bin/env bash
# Quick start, command 1: install what is missing, configure and build (Release), and render the
# default scene (scenes/airfield.json) to out/: one PNG per channel, a panorama, report.json.
# Extra arguments go to `cig render` (e.g. --frames 0:119).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target cig
if [ $# -eq 0 ]; then set -- --frame 0; fi
build/bin/cig render scenes/airfield.json --out out "$@"
