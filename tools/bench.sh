#!/usr/bin/env bash
# The peer in the benchmark: every cig raster engine against Mesa's llvmpipe on the same polygon
# lists (verif/bench/bench_llvmpipe.cpp), written up as verif/bench/RESULTS.md: per list, the CPU
# time of each engine over llvmpipe's, and each image's PSNR against the float engine.
#   tools/bench.sh [--curves | --check | --instructions=OLD_CIG] [--out=DIR] [BUILD_DIR] [benchmark options...]
# BUILD_DIR: default build. Needs libosmesa6-dev (tools/deps.sh). The other options go to the
# benchmark (e.g. --benchmark_filter=depth to try a few lists, --benchmark_min_time=0 for one frame
# a case). --out=DIR: RESULTS.md and the plots written in DIR (a trial; DIR/RESULTS.md starts as a
# copy of verif/bench/RESULTS.md) instead of verif/bench.
#
# Default: the table. Builds bench_llvmpipe, runs every case 3 times for at least 0.5 s each in
# random order (engines and llvmpipe alternate, so a change in the machine's load falls on all
# alike; about 7 minutes on 2 cores), keeps the JSON in BUILD_DIR/bench_llvmpipe.json and rewrites
# the head of RESULTS.md (tools/bench_table.py). Then the load-time benchmark, when
# tools/bench_load_table.py exists: builds and runs bench_load (BUILD_DIR/bench_load.json) and
# writes its section ("load") of RESULTS.md.
#
# --curves: the cost curves (bench_llvmpipe --curves): time against polygon count (1k to 1M small
# triangles), raster size (128 to 1024 lines), samples per pixel (1 to 64) and depth complexity
# (2 to 40), every engine and llvmpipe in the same run, each case 3 times for at least 0.2 s (one
# frame when a frame takes longer) in random order; about 5 minutes on 2 cores while the
# bit-accurate engines refuse lists above 65,536 polygons, at most about 20 minutes if they took
# the 1M list (a 1M-triangle quadtree frame ~15 s, rendered 6 times with its untimed first render);
# about 2 GB of memory (the 1M list and its images).
# Keeps the JSON in BUILD_DIR/bench_curves.json and writes the section "curves" of RESULTS.md and
# its plots verif/bench/curves_AXIS.png (tools/bench_curves.py: tables, plots, growth exponents).
#
# --check: the regression guard, for a developer before a merge (not a test: it times): runs the
# table's cases as the default mode does (the same benchmark options, so a filter checks a few
# lists faster), keeps the JSON in BUILD_DIR/bench_check.json and compares each engine / llvmpipe
# ratio with the one RESULTS.md holds at HEAD (tools/bench_check.py); exit 1, naming the list, the
# engine and both ratios, when one has worsened by more than 15 %; 0 otherwise. Writes no RESULTS.md.
# E.g. tools/bench.sh --check --benchmark_filter='^airfield_f0c1/' (one list, about 1 minute).
#
# --instructions=OLD_CIG: the time-free comparison (tools/bench_instructions.py): callgrind's
# instructions per image inside each engine's render, OLD_CIG (e.g. a build of the merge base)
# against BUILD_DIR's cig on the airfield and depth10 lists; writes the section "instructions".
# About 10 minutes (20 runs under valgrind). Needs valgrind.
#
# Each mode rewrites only its part of RESULTS.md and keeps the others (tools/bench_results.py).
set -euo pipefail
cd "$(dirname "$0")/.."
mode=table build="" out=verif/bench json="" args=()
for arg in "$@"; do
  case $arg in
    --curves) mode=curves ;;
    --check) mode=check ;;
    --instructions=*) mode=instructions old_cig=${arg#--instructions=} ;;
    --out=*) out=${arg#--out=} ;;
    -*) args+=("$arg") ;;
    *) if [[ -z $build && ${#args[@]} -eq 0 ]]; then build=$arg; else args+=("$arg"); fi ;;
  esac
done
build=${build:-build}
results=$out/RESULTS.md
mkdir -p "$out"
[[ -f $results ]] || cp verif/bench/RESULTS.md "$results"
machine="$(lscpu | sed -n 's/^Model name: *//p' | head -1), $(lscpu | sed -n 's/^CPU(s): *//p' | head -1) cores"
commit=$(git rev-parse --short HEAD)
git diff --quiet HEAD -- || commit="$commit with uncommitted changes"
provenance=(--machine "$machine" --date "$(date -u +%Y-%m-%d)" --commit "$commit")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

cmake --build "$build" -j "$(nproc)" --target bench_llvmpipe
run_llvmpipe() {  # JSON, then the benchmark's options
  local json=$1
  shift
  "$build/bin/bench_llvmpipe" --benchmark_enable_random_interleaving=true --benchmark_out="$json" \
    --benchmark_out_format=json "$@"
}

case $mode in
  instructions)
    cmake --build "$build" -j "$(nproc)" --target cig
    python3 tools/bench_instructions.py "$old_cig" "$build/bin/cig" \
      --old-label "before ($("$old_cig" --version | sed -n 's/.*commit \([0-9a-f]\{7\}\).*/\1/p'))" --new-label "after ($commit)" \
      >"$tmp/instructions.md"
    python3 tools/bench_results.py "$results" --section instructions="$tmp/instructions.md" >"$tmp/RESULTS.md"
    ;;
  check)
    json="$build/bench_check.json"
    run_llvmpipe "$json" --benchmark_min_time=0.5 --benchmark_repetitions=3 ${args[@]+"${args[@]}"}
    git show HEAD:verif/bench/RESULTS.md >"$tmp/committed.md"
    status=0
    python3 tools/bench_check.py "$tmp/committed.md" "$json" --label "RESULTS.md at HEAD" || status=$?
    exit $status
    ;;
  curves)
    json="$build/bench_curves.json"
    run_llvmpipe "$json" --curves --benchmark_min_time=0.2 --benchmark_repetitions=3 ${args[@]+"${args[@]}"}
    python3 tools/bench_curves.py "$json" --plots "$out" "${provenance[@]}" >"$tmp/curves.md"
    python3 tools/bench_results.py "$results" --section curves="$tmp/curves.md" >"$tmp/RESULTS.md"
    ;;
  table)
    json="$build/bench_llvmpipe.json"
    run_llvmpipe "$json" --benchmark_min_time=0.5 --benchmark_repetitions=3 ${args[@]+"${args[@]}"}
    python3 tools/bench_table.py "$json" "${provenance[@]}" >"$tmp/head.md"
    sections=()
    if [[ -f tools/bench_load_table.py ]]; then
      cmake --build "$build" -j "$(nproc)" --target bench_load
      "$build/bin/bench_load" --benchmark_out="$build/bench_load.json" --benchmark_out_format=json
      python3 tools/bench_load_table.py "$build/bench_load.json" >"$tmp/load.md"
      sections+=(--section load="$tmp/load.md")
    else
      echo "bench: tools/bench_load_table.py does not exist: the load-time section skipped"
    fi
    python3 tools/bench_results.py "$results" --head "$tmp/head.md" ${sections[@]+"${sections[@]}"} >"$tmp/RESULTS.md"
    ;;
esac
mv "$tmp/RESULTS.md" "$results"
echo "bench: wrote $results${json:+ (raw: $json)}"
