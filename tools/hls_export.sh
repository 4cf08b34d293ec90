#!/bin/bash
# tools/hls_export.sh TOP|all OUTDIR
#
# Writes the HLS hand-off bundle of a *_top kernel (or of every kernel, one folder each under
# OUTDIR) as a self-contained folder:
#   hls/...                  the kernel and type headers it includes (found by the compiler, in both
#                            type configurations: native and -DCIG_HLS_SYSTEMC)
#   src/TOP.cpp              the synthesis top: the kernel's top function at global scope, written
#                            from the kernel's port table (CIG_HLS_PORTS_TOP, beside the kernel)
#   tb/                      the C testbench (tb_TOP.cpp, written here, and the headers it includes)
#   vectors/TOP.vec          the golden vectors it replays (verif/golden/hls/)
#   hls_config.cfg           Vitis HLS unified flow (v++ -c --mode hls): part, top, files,
#                            testbench, 100 MHz, interfaces
#   run_vitis.tcl            Vitis HLS Tcl flow: the same, then csim / csynth / cosim
#   run_catapult.tcl         Catapult HLS: the same steps
#   README.md                the top, its signature, its ports and their bit widths, how to build
#                            and run
# The testbench builds from the folder alone:
#   g++ -std=c++14 -I. tb/tb_TOP.cpp src/TOP.cpp -o tb && ./tb              (native types: C++14, as the HLS tools)
#   g++ -std=c++17 -DCIG_HLS_SYSTEMC -I. tb/tb_TOP.cpp src/TOP.cpp -lsystemc -o tb && ./tb
#     (SystemC types: the standard Debian's libsystemc was built with; its headers check it at link time)
# and exits 0 when every vector matches, 1 on a difference, 2 on a missing or malformed vector file.
#
# OUTDIR is new, empty, or a folder this script wrote before: every folder it writes holds a marker,
# .cig-hls-bundle (the top, the cig version and commit, and the manifest of the files written), and
# a later export replaces or removes only the files of that manifest; anything else there (a
# user's notes) stays. The new bundle is copied next to the old one and then moved in, so that a
# failure while copying leaves the old bundle whole. Refused (exit 2) before anything is written: a
# non-empty folder without the marker, an existing non-folder, the source tree, a parent of it,
# $HOME and its parents (symlinks and .. resolved first).
set -euo pipefail

repo=$(realpath "$(dirname "$0")/..")
tb_dir=$repo/verif/hls_export/tb
marker=.cig-hls-bundle
# shellcheck disable=SC2034  # read by tools/lib/output_folder.sh
of_prog=tools/hls_export.sh
# shellcheck source-path=SCRIPTDIR source=lib/output_folder.sh
source "$repo/tools/lib/output_folder.sh"
# The tops: every port table in hls/ (hls/types/top_ports.hpp), and the header that holds it.
tops() {
  grep -rhoE --include='*.hpp' '^#define CIG_HLS_PORTS_[A-Za-z0-9_]+_top\(' "$repo/hls" |
    sed 's/^#define CIG_HLS_PORTS_//; s/($//' | sort
}
kernel_header() { grep -rlE --include='*.hpp' "^#define CIG_HLS_PORTS_$1\\(" "$repo/hls" | head -1; }

usage() {
  cat <<EOF
usage: tools/hls_export.sh TOP|all OUTDIR
Writes the HLS hand-off bundle of TOP into OUTDIR, or with "all" every top's into OUTDIR/TOP.
OUTDIR must be new, empty, or a folder this script wrote before (it holds $marker): there it
replaces or removes only the files it wrote, and leaves every other file in place. Never the
source tree, a parent of it, \$HOME or a parent of it.
TOP: $(tops | tr '\n' ' ')
EOF
}
for arg in "$@"; do
  case $arg in -h | --help) usage; exit 0 ;; esac
done
if [ $# -ne 2 ] || [ -z "$2" ]; then
  usage >&2
  exit 2
fi
top=$1
out=$2
if [ "$top" != all ] && ! tops | grep -qx -- "$top"; then
  echo "tools/hls_export.sh: '$top' is not a kernel top" >&2
  usage >&2
  exit 2
fi
command -v g++ >/dev/null || { echo "tools/hls_export.sh: needs g++ (apt-get install g++)" >&2; exit 2; }

# Every check before anything is written: the place, the folder's owner, each top's folder and
# vectors.
check_bundle_folder() {  # folder top
  of_check_place "$1" "$repo"
  of_check_claim "$1" "$marker"
  local real
  real=$(of_resolve "$1")
  if of_has_marker "$real" "$marker" && [ "$(of_marker_value "$real" "$marker" top)" = all ]; then
    of_fail "$(of_shown "$1"): holds the bundles of every top (tools/hls_export.sh all); export $2 into" \
      "$1/$2, or into a new or empty folder"
  fi
  [ -f "$repo/verif/golden/hls/$2.vec" ] || of_fail "$repo/verif/golden/hls/$2.vec: no golden vectors"
}
if [ "$top" = all ]; then
  of_check_place "$out" "$repo"
  of_check_claim "$out" "$marker"
  for t in $(tops); do check_bundle_folder "$out/$t" "$t"; done
else
  check_bundle_folder "$out" "$top"
fi

version=$(sed -n 's/^project(cig VERSION \([0-9.]*\).*/\1/p' "$repo/CMakeLists.txt")
commit=$(git -C "$repo" rev-parse HEAD 2>/dev/null) || commit=unknown
if [ "$commit" != unknown ] && ! git -C "$repo" diff --quiet HEAD -- 2>/dev/null; then commit=$commit-dirty; fi
marker_header() {  # top [extra lines]
  printf '%s\n' "${marker#.} 1" "top $1" "version $version" "commit $commit" "date $(date -u +%Y-%m-%dT%H:%M:%SZ)" \
    "written_by tools/hls_export.sh"
  [ $# -lt 2 ] || printf '%s\n' "$2"
}

# Every file of the tree the testbench (the staged tb/tb_TOP.cpp) and the kernel include, in both
# configurations.
dependencies() {
  local flags
  for flags in "" "-DCIG_HLS_SYSTEMC"; do
    g++ -std=c++14 $flags -I"$repo" -I"$tb_dir" -MM -MG "$staging/tb/tb_$top.cpp" "$kernel"
  done | tr ' \\' '\n\n' | grep -v ':$' | grep -v '^$' | sort -u
}

# The port table as the preprocessor expands it, one entry a line: "result TYPE",
# "port NAME DIRECTION INTERFACE TYPE", "array NAME DIRECTION INTERFACE EXTENT ELEMENT".
table_rows() {
  printf '%s\n' "#include \"${kernel#"$repo"/}\"" '#define CIG_ROW_RESULT(t) @result t' \
    '#define CIG_ROW_PORT(n, d, i, t) @port n d i t' '#define CIG_ROW_ARRAY(n, d, i, e, x) @array n d i x e' \
    "@rows CIG_HLS_PORTS_$top(CIG_ROW_PORT, CIG_ROW_ARRAY, CIG_ROW_RESULT)" |
    g++ -std=c++14 -E -P -x c++ -I"$repo" - | sed -n 's/^@rows *//p' | sed 's/ *@/\n/g' | grep -v '^$'
}

# src/TOP.cpp: the kernel at global scope as a plain function (the table's types, unqualified).
write_syn_top() {
  local rows result params args lead call
  rows=$(table_rows)
  result=$(echo "$rows" | sed -n 's/^result //p')
  [ -n "$result" ] || of_fail "$top: no port table in ${kernel#"$repo"/}"
  params=$(echo "$rows" | awk '
    $1 == "port" { t = $0; sub(/^port [^ ]+ [^ ]+ [^ ]+ /, "", t); print t " " $2 }
    $1 == "array" { e = $0; sub(/^array [^ ]+ [^ ]+ [^ ]+ [^ ]+ /, "", e); print e " (&" $2 ")[" $5 "]" }')
  args=$(echo "$rows" | awk '$1 == "port" || $1 == "array" { printf "%s%s", (n++ ? ", " : ""), $2 }')
  lead=$(printf '%*s' $((${#result} + ${#top} + 2)) '')
  call="return cig::hls::$top($args);"
  [ "$result" != void ] || call="cig::hls::$top($args);"
  cat > "$staging/src/$top.cpp" <<EOF
// Synthesis top: the kernel at global scope, the name syn.top, set_top and Catapult's design
// take, and the function the testbench calls, so that C/RTL co-simulation puts the RTL in its
// place. Written by tools/hls_export.sh from the kernel's port table, its signature written once
// beside the kernel: CIG_HLS_PORTS_$top in ${kernel#"$repo"/}.
#include "${kernel#"$repo"/}"

using namespace cig::hls;  // the port types, named as in the table

$result $top($(echo "$params" | sed "2,\$s/^/$lead/; \$!s/\$/,/")) {
  $call
}
EOF
}

# tb/tb_TOP.cpp: the testbench's main for the case tb/TOP.hpp.
write_tb_main() {
  cat > "$staging/tb/tb_$top.cpp" <<EOF
// Testbench: replays the golden vectors through the synthesis top and exits non-zero on any
// difference (tb_main.hpp; the case, its inputs, outputs and call from the kernel's port table:
// $top.hpp). Written by tools/hls_export.sh.
#include "$top.hpp"
#include "tb_main.hpp"

CIG_TB_MAIN($top)
EOF
}

# The ports as the testbench prints them (--ports, from the port table): name, direction,
# interface and bits. The interfaces are the table's; a port that is not a memory and is wider
# than 64 bits (a record) travels as one word, its fields packed (aggregate, compact bit).
port_rows() {
  echo "$ports" | awk -F'|' '{gsub(/[` ]/, "", $2); gsub(/ /, "", $3); gsub(/ /, "", $4); gsub(/ /, "", $6);
    if ($2 != "return") print $2, $3, $4, $6}'
}
aggregated() { [ "$2" != ap_memory ] && [ "$3" -gt 64 ]; }  # direction interface bits

vitis_interfaces() {  # FORMAT: tcl or cfg
  port_rows | while read -r name dir mode bits; do
    if [ "$1" = tcl ]; then
      if aggregated "$dir" "$mode" "$bits"; then echo "set_directive_aggregate -compact bit $top $name"; fi
      echo "set_directive_interface -mode $mode $top $name"
    else
      if aggregated "$dir" "$mode" "$bits"; then echo "syn.directive.aggregate=$top $name compact=bit"; fi
      echo "syn.directive.interface=$top $name mode=$mode"
    fi
  done
}

write_vitis_cfg() {
  cat > "$staging/hls_config.cfg" <<EOF
# Vitis HLS unified flow (2023.2 and later, 2025.x), run from the bundle's folder (W: proj_TOP):
#   v++ -c --mode hls --config hls_config.cfg --work_dir W              synthesis
#   vitis-run --mode hls --csim --config hls_config.cfg --work_dir W    C simulation
#   vitis-run --mode hls --cosim --config hls_config.cfg --work_dir W   C/RTL co-simulation
# Paths are the bundle's (this file's folder). The testbench replays vectors/TOP.vec, or the copy
# tb.file puts where it runs, and exits non-zero on any difference. The part (xcvu9p) is a
# placeholder for your own. Written by tools/hls_export.sh.
part=xcvu9p-flga2104-2-i

[hls]
flow_target=vivado
clock=10ns
syn.top=$top
syn.file=src/$top.cpp
syn.cflags=-std=c++14 -I.
tb.file=tb/tb_$top.cpp
tb.file=vectors/$top.vec
tb.cflags=-std=c++14 -I.
cosim.rtl=verilog
# Interfaces (README.md, "Ports"): the block protocol, then each port as its table sets it.
syn.directive.interface=$top mode=ap_ctrl_hs
$(vitis_interfaces cfg)
EOF
}

write_vitis() {
  cat > "$staging/run_vitis.tcl" <<EOF
# Vitis HLS, Tcl flow: vitis_hls -f run_vitis.tcl (2023.2; from 2024.2 also
# vitis-run --mode hls --tcl run_vitis.tcl). Written by tools/hls_export.sh. C simulation (the
# testbench replays the golden vectors and exits non-zero on any difference), synthesis at
# 100 MHz, C/RTL co-simulation with the same testbench and vectors. The unified flow: hls_config.cfg.
set here [file normalize [file dirname [info script]]]
open_project -reset proj_$top
set_top $top
add_files \$here/src/$top.cpp -cflags "-std=c++14 -I\$here"
add_files -tb \$here/tb/tb_$top.cpp -cflags "-std=c++14 -I\$here"
open_solution -reset solution1 -flow_target vivado
set_part {xcvu9p-flga2104-2-i}
create_clock -period 10 -name default
# Interfaces (README.md, "Ports").
set_directive_interface -mode ap_ctrl_hs $top return
$(vitis_interfaces tcl)
csim_design -argv "\$here/vectors/$top.vec"
csynth_design
cosim_design -argv "\$here/vectors/$top.vec" -rtl verilog
exit
EOF
}

catapult_interfaces() {
  port_rows | while read -r name dir mode bits; do
    if [ "$mode" = ap_memory ]; then
      echo "directive set /$top/$name:rsc -MAP_TO_MODULE ccs_sample_mem.ccs_ram_sync_1R1W"
    elif [ "$dir" = in ]; then
      echo "directive set /$top/$name:rsc -MAP_TO_MODULE ccs_ioport.ccs_in"
    else
      echo "directive set /$top/$name:rsc -MAP_TO_MODULE ccs_ioport.ccs_out_vld"
    fi
  done
}

write_catapult() {
  cat > "$staging/run_catapult.tcl" <<EOF
# Catapult HLS: catapult -shell -file run_catapult.tcl. Written by tools/hls_export.sh.
# SCVerify builds the testbench with CCS_SCVERIFY, so it calls the top through CCS_DESIGN
# (tb/vector_io.hpp, CIG_TB_DESIGN) and one testbench checks the C++ and the RTL.
set here [file normalize [file dirname [info script]]]
project new -name proj_$top -directory \$here/catapult
options set Input/CppStandard c++14
options set Input/SearchPath \$here -append
flow package require /SCVerify
flow package option set /SCVerify/INVOKE_ARGS "\$here/vectors/$top.vec"
solution file add \$here/src/$top.cpp -type C++
solution file add \$here/tb/tb_$top.cpp -type C++ -exclude true
solution design set $top -top
go analyze
go compile
solution library add mgc_Xilinx-VIRTEX-uplus-2_beh -- -rtlsyntool Vivado -manufacturer Xilinx -family VIRTEX-uplus -speed -2 -part xcvu9p-flga2104-2-i
go libraries
directive set -CLOCKS {clk {-CLOCK_PERIOD 10.0 -CLOCK_EDGE rising -RESET_KIND sync -RESET_SYNC_NAME rst -RESET_SYNC_ACTIVE high}}
go assembly
# Interfaces (README.md, "Ports"): memories and tables as RAM ports, records as wide I/O.
$(catapult_interfaces)
go architect
go allocate
go extract
# C simulation of the original C++, then C/RTL co-simulation of the generated Verilog.
flow run /SCVerify/launch_make ./scverify/Verify_orig_cxx_osci.mk {} SIMTOOL=osci sim
flow run /SCVerify/launch_make ./scverify/Verify_rtl_v_msim.mk {} SIMTOOL=msim sim
project save
EOF
}

write_readme() {
  local count signature
  count=$(grep -c '^>' "$vectors")
  signature=$(sed -n "/^[^/ ].* $top(/,/) {\$/p" "$staging/src/$top.cpp" | sed '$ s/ {$/;/')
  cat > "$staging/README.md" <<EOF
# HLS hand-off bundle: \`$top\`

Written by \`tools/hls_export.sh $top OUTDIR\` from the cig source tree. Self-contained: the
kernel's headers (\`hls/\`: C++14, the HLS subset, no dynamic memory, no floating point), its
synthesis top (\`src/$top.cpp\`: \`$top\` at global scope, the name the tools' top setting
takes), a C++ testbench (\`tb/\`) and $count golden vectors (\`vectors/$top.vec\`) written by the
C model. \`.cig-hls-bundle\` lists the files the script wrote: a later export into this folder
replaces or removes only those, and leaves any other file (your notes) in place.

Targeted tools: Vitis HLS 2023.2 and later (the unified flow, \`hls_config.cfg\`, as in 2025.x;
the Tcl flow, \`run_vitis.tcl\`) and Catapult HLS (\`run_catapult.tcl\`). C++ standard: C++14,
the common subset of both; every file here compiles with \`-std=c++14 -pedantic-errors\`.

## Signature

The kernel's signature is written once, as its port table \`CIG_HLS_PORTS_$top\` beside the
kernel in \`${kernel#"$repo"/}\` (\`hls/types/top_ports.hpp\`); the kernel, \`src/$top.cpp\`, the
testbench's case (\`tb/$top.hpp\`) and the table below are expanded from it. Expanded (the types
are in namespace \`cig::hls\`):

\`\`\`c++
$signature
\`\`\`

## Ports

Bits are the C++ record's bits: the concatenation of its fields in the order listed (arrays:
elements x bits). Interfaces as the port table gives them and \`hls_config.cfg\` and
\`run_vitis.tcl\` set them: block protocol \`ap_ctrl_hs\` (the return value, if any, on
\`ap_return\`, valid with \`ap_done\`); memories and tables \`ap_memory\`; inputs \`ap_none\`;
outputs \`ap_vld\`, in-out registers \`ap_ovld\`; a record of more than 64 bits that is not a
memory aggregated into one word, its fields packed (\`compact=bit\`).

| port | direction | interface | C++ type | bits | fields (bits) |
|---|---|---|---|---|---|
$ports

## Build and run the testbench

\`\`\`
g++ -std=c++14 -pedantic-errors -O1 -I. tb/tb_$top.cpp src/$top.cpp -o tb_$top && ./tb_$top
g++ -std=c++17 -O1 -DCIG_HLS_SYSTEMC -I. tb/tb_$top.cpp src/$top.cpp -lsystemc -o tb_$top && ./tb_$top
\`\`\`

The first is C++14, what Vitis HLS and Catapult compile. The second maps the bit-accurate types
onto SystemC's \`sc_int\`/\`sc_uint\` (Debian: libsystemc-dev) and takes C++17, the standard
that library was built with (SystemC's headers check it when linking); both must pass. Exit
status: 0 every vector matches, 1 a difference (each differing vector and its first differing
field are printed), 2 a missing or malformed vector file. \`./tb_$top --ports\` prints the table
above; \`./tb_$top FILE\` replays another file.

## Synthesis

- Vitis HLS, unified flow (2023.2 and later): \`v++ -c --mode hls --config hls_config.cfg
  --work_dir proj_$top\` synthesises; \`vitis-run --mode hls --csim\` (or \`--cosim\`) with the
  same \`--config\` and \`--work_dir\` runs C simulation (C/RTL co-simulation).
- Vitis HLS, Tcl flow: \`vitis_hls -f run_vitis.tcl\` (from 2024.2 also \`vitis-run --mode hls
  --tcl run_vitis.tcl\`).
- Catapult HLS: \`catapult -shell -file run_catapult.tcl\`.

Each sets the top, the files, the testbench, a 100 MHz clock (10 ns) and the interfaces; the Tcl
scripts then run C simulation, synthesis and C/RTL co-simulation with the same vectors. The part
(xcvu9p) is a placeholder for your own. The files are written from the tools' documented commands;
neither tool runs on the machine that builds cig, so they are not exercised by its tests (the
testbench and the vectors are, and the configuration's top and files are checked).

## Kernel headers

$(echo "$headers" | sed 's/^/- `/; s/$/`/')
EOF
}

# TOP's bundle, staged in $stage_root/TOP (nothing is written to OUTDIR yet): first its files (the
# synthesis top and the testbench's main from the port table, the headers, the vectors; the scripts
# and the README empty), which is all the check of its folder needs, then the scripts and the
# README (the port table with its widths needs the testbench compiled, the slow part).
stage_top_files() {
  local f
  staging=$stage_root/$top
  kernel=$(kernel_header "$top")
  mkdir -p "$staging/src" "$staging/tb" "$staging/vectors"
  write_syn_top
  write_tb_main
  for f in $(dependencies); do
    f=$(realpath "$f")
    case $f in
      "$staging"/*) ;;
      "$repo"/hls/*) mkdir -p "$staging/$(dirname "${f#"$repo"/}")"; cp "$f" "$staging/${f#"$repo"/}" ;;
      "$tb_dir"/*) cp "$f" "$staging/tb/" ;;
      *) echo "tools/hls_export.sh: $f: a dependency outside hls/ and the testbench" >&2; exit 2 ;;
    esac
  done
  cp "$repo/verif/golden/hls/$top.vec" "$staging/vectors/"
  touch "$staging/hls_config.cfg" "$staging/run_vitis.tcl" "$staging/run_catapult.tcl" "$staging/README.md"
}

stage_top_generated() {
  vectors=$repo/verif/golden/hls/$top.vec
  staging=$stage_root/$top
  # The port table with its widths (the testbench prints it) for the README and the interface
  # directives; -O0: it only prints the table. Building it also builds the synthesis top.
  g++ -std=c++14 -O0 -I"$staging" "$staging/tb/tb_$top.cpp" "$staging/src/$top.cpp" -o "$stage_root/tb_$top"
  ports=$("$stage_root/tb_$top" --ports)
  rm -f "$stage_root/tb_$top"
  headers=$(cd "$staging" && find hls -name '*.hpp' | sort)
  write_vitis_cfg
  write_vitis
  write_catapult
  write_readme
}

# Every bundle is staged and checked against its folder before the first file is written there.
stage_root=$(mktemp -d)
of_cleanup+=("$stage_root")
if [ "$top" = all ]; then
  selected=$(tops)
  mkdir "$stage_root/.outdir"  # OUTDIR itself holds no file of its own, only its marker
  folder_of() { echo "$out/$1"; }
else
  selected=$top
  folder_of() { echo "$out"; }
fi
for top in $selected; do
  stage_top_files
  of_check_install "$stage_root/$top" "$(folder_of "$top")" "$marker"
done
for top in $selected; do stage_top_generated; done

if [ -d "$stage_root/.outdir" ]; then
  # OUTDIR's marker first, so that an interrupted run can be repeated; then one bundle per top.
  of_install "$stage_root/.outdir" "$out" "$marker" "$(marker_header all "$(tops | sed 's/^/bundle /')")"
fi
for top in $selected; do
  of_install "$stage_root/$top" "$(folder_of "$top")" "$marker" "$(marker_header "$top")"
  headers=$(cd "$stage_root/$top" && find hls -name '*.hpp' | wc -l)
  echo "$(folder_of "$top"): $top ($headers kernel headers, $(grep -c '^>' "$repo/verif/golden/hls/$top.vec") vectors)"
done
