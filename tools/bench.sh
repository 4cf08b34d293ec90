#!/usr/bin/env bash
# The peer in the benchmark: every cig raster engine against Mesa's llvmpipe on the same polygon
# lists (verif/bench/bench_llvmpipe.cpp), written up as verif/bench/RESULTS.md: per list, the CPU
# time of each engine over llvmpipe's, and each image's PSNR against the float engine.
#   tools/bench.sh [BUILD_DIR] [benchmark options...]     BUILD_DIR: default build, configured
# Builds bench_llvmpipe (needs libosmesa6-dev: tools/deps.sh), runs every case 3 times for at least
# 0.5 s each in random order (engines and llvmpipe alternate, so a change in the machine's load
# falls on all alike; about 7 minutes on 2 cores) and keeps the JSON in BUILD_DIR/bench_llvmpipe.json.
# Options after BUILD_DIR go to the benchmark (e.g. --benchmark_filter=depth to try a few lists).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
shift $(($# > 0 ? 1 : 0))
cmake --build "$build" -j "$(nproc)" --target bench_llvmpipe
json="$build/bench_llvmpipe.json"
"$build/bin/bench_llvmpipe" --benchmark_min_time=0.5 --benchmark_repetitions=3 \
  --benchmark_enable_random_interleaving=true --benchmark_out="$json" --benchmark_out_format=json "$@"
machine="$(lscpu | sed -n 's/^Model name: *//p' | head -1), $(lscpu | sed -n 's/^CPU(s): *//p' | head -1) cores"
commit=$(git rev-parse --short HEAD)
git diff --quiet HEAD -- || commit="$commit with uncommitted changes"
python3 tools/bench_table.py "$json" --machine "$machine" --date "$(date -u +%Y-%m-%d)" --commit "$commit" \
  >verif/bench/RESULTS.md.tmp
mv verif/bench/RESULTS.md.tmp verif/bench/RESULTS.md
echo "bench: wrote verif/bench/RESULTS.md (raw: $json)"
