#!/bin/bash
# tools/hls_export.sh TOP|all OUTDIR
#
# Writes the HLS hand-off bundle of a *_top kernel (or of every kernel, one folder each under
# OUTDIR) as a self-contained folder:
#   hls/...                  the kernel and type headers it includes (found by the compiler, in both
#                            type configurations: native and -DCIG_HLS_SYSTEMC)
#   src/TOP.cpp              the synthesis top: the kernel's top function at global scope
#   tb/                      the C testbench (tb_TOP.cpp and the headers it includes)
#   vectors/TOP.vec          the golden vectors it replays (verif/golden/hls/)
#   run_vitis.tcl            Vitis HLS: project, top, files, testbench, 100 MHz, interfaces,
#                            csim / csynth / cosim
#   run_catapult.tcl         Catapult HLS: the same steps
#   README.md                the top, its ports and their bit widths, how to build and run
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
tops() { ls "$repo/verif/hls_export/syn" | sed -n 's/\.cpp$//p'; }

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

# Every file of the tree the testbench and the synthesis top include, in both configurations.
dependencies() {
  local flags
  for flags in "" "-DCIG_HLS_SYSTEMC"; do
    g++ -std=c++14 $flags -I"$repo" -I"$repo/verif/hls_export" -MM -MG \
      "$tb_dir/tb_$top.cpp" "$repo/verif/hls_export/syn/$top.cpp"
  done | tr ' \\' '\n\n' | grep -v ':$' | grep -v '^$' | sort -u
}

# Interface of a port, from its direction and width (the --ports table): memories and tables
# (64 Kbit and more) stay memories the kernel addresses (ap_memory: the frame memory, the segment memory,
# the mask memory, the colour and fog tables); records travel as one wide word (aggregated),
# inputs without handshake (ap_none, valid with ap_start), outputs with a valid strobe (ap_vld;
# ap_ovld for in-out); the block protocol is ap_ctrl_hs (start, done, idle, ready).
interface_of() {  # direction bits
  if [ "$2" -ge 65536 ]; then echo ap_memory
  elif [ "$1" = in ]; then echo ap_none
  elif [ "$1" = inout ]; then echo ap_ovld
  else echo ap_vld
  fi
}
port_rows() { echo "$ports" | awk -F'|' '{gsub(/[` ]/, "", $2); gsub(/ /, "", $3); gsub(/ /, "", $5); print $2, $3, $5}'; }

vitis_interfaces() {
  port_rows | while read -r name dir bits; do
    [ "$name" = return ] && continue
    mode=$(interface_of "$dir" "$bits")
    if [ "$mode" != ap_memory ] && [ "$bits" -gt 64 ]; then echo "set_directive_aggregate -compact bit $top $name"; fi
    echo "set_directive_interface -mode $mode $top $name"
  done
}

write_vitis() {
  cat > "$staging/run_vitis.tcl" <<EOF
# Vitis HLS: vitis_hls -f run_vitis.tcl. Written by tools/hls_export.sh.
# C simulation (the testbench replays vectors/$top.vec and exits non-zero on any difference),
# synthesis at 100 MHz, C/RTL co-simulation with the same testbench and vectors.
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
$(vitis_interfaces)
csim_design -argv "\$here/vectors/$top.vec"
csynth_design
cosim_design -argv "\$here/vectors/$top.vec" -rtl verilog
exit
EOF
}

catapult_interfaces() {
  port_rows | while read -r name dir bits; do
    [ "$name" = return ] && continue
    if [ "$(interface_of "$dir" "$bits")" = ap_memory ]; then
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
  local count
  count=$(grep -c '^>' "$vectors")
  cat > "$staging/README.md" <<EOF
# HLS hand-off bundle: \`$top\`

Written by \`tools/hls_export.sh $top OUTDIR\` from the cig source tree. Self-contained: the
kernel's headers (\`hls/\`: C++17, the HLS subset, no dynamic memory, no floating point), its
synthesis top (\`src/$top.cpp\`: \`$top\` at global scope, the name \`set_top\` takes), a C
testbench (\`tb/\`) and $count golden vectors (\`vectors/$top.vec\`) written by the C model.
\`.cig-hls-bundle\` lists the files the script wrote: a later export into this folder replaces or
removes only those, and leaves any other file (your notes) in place.

## Ports

Bits are the C++ record's bits: the concatenation of its fields in the order listed (arrays:
elements x bits). Interfaces as \`run_vitis.tcl\` sets them: block protocol \`ap_ctrl_hs\`; ports
of 64 Kbit and more (memories, tables) \`ap_memory\`; records aggregated into one word; inputs
\`ap_none\`, outputs \`ap_vld\`, in-out \`ap_ovld\`.

| port | direction | C++ type | bits | fields (bits) |
|---|---|---|---|---|
$ports

## Build and run the testbench

\`\`\`
g++ -std=c++14 -O1 -I. tb/tb_$top.cpp src/$top.cpp -o tb_$top && ./tb_$top
g++ -std=c++17 -O1 -DCIG_HLS_SYSTEMC -I. tb/tb_$top.cpp src/$top.cpp -lsystemc -o tb_$top && ./tb_$top
\`\`\`

The first is C++14, what Vitis HLS and Catapult compile. The second maps the bit-accurate types
onto SystemC's \`sc_int\`/\`sc_uint\` (Debian: libsystemc-dev) and takes C++17, the standard
that library was built with (SystemC's headers check it when linking); both must pass. Exit status: 0 every vector matches, 1 a difference (each
differing vector and its first differing field are printed), 2 a missing or malformed vector
file. \`./tb_$top --ports\` prints the table above; \`./tb_$top FILE\` replays another file.

## Synthesis

\`vitis_hls -f run_vitis.tcl\` or \`catapult -shell -file run_catapult.tcl\`: project, top, files,
testbench, 100 MHz clock (10 ns), interfaces, then C simulation, synthesis and C/RTL
co-simulation with the same vectors. The part (xcvu9p) is a placeholder for your own. The
scripts are written from the tools' documented commands; neither tool runs on the machine that
builds cig, so they are not exercised by its tests (the testbench and the vectors are).

## Kernel headers

$(echo "$headers" | sed 's/^/- `/; s/$/`/')
EOF
}

# TOP's bundle, staged in $stage_root/TOP (nothing is written to OUTDIR yet): first its files (the
# headers, the tops, the vectors; the generated ones empty), which is all the check of its folder
# needs, then the generated files (the port table needs the testbench compiled, the slow part).
stage_top_files() {
  local f
  staging=$stage_root/$top
  mkdir -p "$staging/src" "$staging/tb" "$staging/vectors"
  for f in $(dependencies); do
    f=$(realpath "$f")
    case $f in
      "$repo"/hls/*) mkdir -p "$staging/$(dirname "${f#$repo/}")"; cp "$f" "$staging/${f#$repo/}" ;;
      "$tb_dir"/*) cp "$f" "$staging/tb/" ;;
      "$repo"/verif/hls_export/syn/*) cp "$f" "$staging/src/" ;;
      *) echo "tools/hls_export.sh: $f: a dependency outside hls/ and the testbench" >&2; exit 2 ;;
    esac
  done
  cp "$repo/verif/golden/hls/$top.vec" "$staging/vectors/"
  touch "$staging/run_vitis.tcl" "$staging/run_catapult.tcl" "$staging/README.md"
}

stage_top_generated() {
  vectors=$repo/verif/golden/hls/$top.vec
  staging=$stage_root/$top
  # The port table (the testbench prints it) for the README; -O0: it only prints the table.
  g++ -std=c++14 -O0 -I"$staging" "$staging/tb/tb_$top.cpp" "$staging/src/$top.cpp" -o "$stage_root/tb_$top"
  ports=$("$stage_root/tb_$top" --ports)
  rm -f "$stage_root/tb_$top"
  headers=$(cd "$staging" && find hls -name '*.hpp' | sort)
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
