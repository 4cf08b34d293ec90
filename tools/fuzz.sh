#!/usr/bin/env bash
# Long local fuzzing run: tools/fuzz.sh TARGET MINUTES (TARGET: scene_loader, model_loader,
# polygon_list, raster, options; "all" runs each in turn). Builds the libFuzzer targets with clang,
# ASan and UBSan in build-fuzz/ (tools/deps.sh installs clang) and runs the target's ctest for
# MINUTES: each run starts from the seeds (scenes/, verif/bad_input/; verif/fuzz/CMakeLists.txt lists
# them per target) in a fresh corpus, build-fuzz/verif/fuzz/run_TARGET/. A crash, leak, hang (> 10 s per input) or
# sanitizer report stops the run with status 1 and leaves the input in .../run_TARGET/artifacts/:
# add it to verif/bad_input/ as a regression case (verif/fuzz/README.md).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -ne 2 ] || ! [[ $2 =~ ^[0-9]+$ ]] || [ "$2" -lt 1 ]; then
  echo "usage: tools/fuzz.sh TARGET|all MINUTES" >&2
  exit 2
fi
tools/deps.sh
if [ ! -f build-fuzz/CMakeCache.txt ]; then
  CXX=clang++ tools/configure.sh build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCIG_SANITIZE=ON -DCIG_FUZZ=ON \
    -DCIG_BUILD_TESTS=ON -DCIG_WITH_RTL=OFF
fi
targets=$1
[ "$targets" = all ] && targets="scene_loader model_loader polygon_list raster options"
for t in $targets; do
  cmake --build build-fuzz -j"$(nproc)" --target "fuzz_$t"
  cmake -DCIG_FUZZ_SECONDS=$(($2 * 60)) build-fuzz >/dev/null
  ctest --test-dir build-fuzz -R "^fuzz\.$t\$" --output-on-failure --timeout $(($2 * 60 + 300))
done
