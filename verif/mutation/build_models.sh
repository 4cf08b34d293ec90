#!/usr/bin/env bash
# Verilates the mutated RTL copy for mutation testing (CMakeLists.txt here, custom command):
#   build_models.sh VERILATOR MUTANT_DIR COSIM_TB OUT_DIR PREFIX P1 P2 [P1_ADD]
# MUTANT_DIR holds rtl/ (the copy of rtl/quadtree/ or rtl/invparam/), sources.txt
# (rtl/quadtree/qt_sources.cmake's or rtl/invparam/ip_sources.cmake's order) and configs (the
# configurations to build, "A_B ...": the values of the cosim wrapper's parameters P1 and P2, e.g.
# N_LOG2 TREE_LEVELS "6_1 6_2" or W N_PP "64_8 57_16"; P1 gets A + P1_ADD, default 0: stage F's
# configurations name the seed's word, its RTL's W is the register width, the word + 16 guard
# bits). Each configuration gets the co-simulation's Verilator options and prefix (PREFIX, a
# printf format of A, then B: Vqt_raster_n%s_t gives Vqt_raster_n6_t1, what the mutant runners
# include; the top module is COSIM_TB's name) without FST tracing; the generated C++ is compiled at
# -O0 by Verilator's own make (these models run the small N = 64 tests once: build time is what
# counts). A configuration not asked for is removed, so that rtl_runner_mutant.cpp (__has_include)
# cannot pick up a stale one.
# Output: OUT_DIR/libcig_rtl_mutant_models.a (every configuration's classes) and OUT_DIR/stamp.
set -euo pipefail
verilator=$1 mut=$2 tb=$3 out=$4 prefix_head=$5 p1=$6 p2=$7 p1_add=${8:-0}
read -r -a names < "$mut/sources.txt"
read -r -a configs < "$mut/configs"
sources=()
for n in "${names[@]}"; do sources+=("$mut/rtl/$n"); done
mkdir -p "$out"
for old in "$out"/obj_*; do
  [ -d "$old" ] || continue
  keep=0
  for c in "${configs[@]}"; do [ "$old" = "$out/obj_$c" ] && keep=1; done
  [ $keep = 1 ] || rm -rf "$old"
done
build_one() {
  local a=${1%_*} b=${1#*_}
  local prefix dir=$out/obj_$1
  # shellcheck disable=SC2059  # PREFIX is the format
  prefix=$(printf "$prefix_head" "$a")$b
  rm -rf "$dir"
  "$verilator" --cc --prefix "$prefix" --top-module "$(basename "$tb" .sv)" -Mdir "$dir" \
    -G"$p1"="$((a + p1_add))" -G"$p2"="$b" --x-assign fast --x-initial fast -O3 "${sources[@]}" "$tb"
  make -s -j"$jobs" -C "$dir" -f "$prefix.mk" OPT_FAST=-O0 OPT_SLOW=-O0 OPT_GLOBAL=-O0 CXXFLAGS=-w "${prefix}__ALL.a"
}
jobs=$((${#configs[@]} > 1 ? 1 : 2))   # two compile jobs in all (the machine's cores)
pids=()
for c in "${configs[@]}"; do
  build_one "$c" > "$out/build_$c.log" 2>&1 &
  pids+=($!)
done
status=0
for k in "${!pids[@]}"; do
  if ! wait "${pids[$k]}"; then
    status=1
    echo "build_models.sh: configuration ${configs[$k]} failed:" >&2
    tail -30 "$out/build_${configs[$k]}.log" >&2
  fi
done
[ $status = 0 ] || exit 1
rm -f "$out/libcig_rtl_mutant_models.a"
objects=()
for c in "${configs[@]}"; do objects+=("$out/obj_$c"/*.o); done
ar -rcs "$out/libcig_rtl_mutant_models.a" "${objects[@]}"
touch "$out/stamp"
