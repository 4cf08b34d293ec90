#!/usr/bin/env bash
# Synthesis report of the RTL (rtl/quadtree/, rtl/invparam/) with Debian's yosys 0.23: per module
# the cell count, the transistor estimate of `stat -tech cmos` and the longest combinational path
# in cells (`ltp -noff` on the module flattened), for
#   pe_mid     qt_pe alone at a middle level (N_LOG2 = 9, LEVEL = 5), default widths;
#   pe_pixel   qt_pe alone at the pixel level (N_LOG2 = 9, LEVEL = 9), default widths;
#   raster     a whole architecture, small: qt_raster N_LOG2 = 4, TREE_LEVELS = 2 (2p2t: 7 PEs,
#              4 pixel processors), the coarse format's widths (G = 6, PW = 35, GW = 20), 2 light
#              covers, a 16-entry fog table (FOG_CODE_BITS = 4), so that its memories stay small
#              and the run takes minutes on 2 cores;
#   ip_pe_57   stage F's pixel processor (ip_pe) for the seed's 57-bit word (10 km): registers of
#              W = 73 bits (the word and 16 guard bits, hls Word<57>);
#   ip_pe_64   the same for the seed's 64-bit word (100 km, its "six 64-bit registers"): W = 80;
#   ip_array_16  ip_array of N_PP = 16 PPs at W = 80 (the chain, the VT bus, the handshake).
# Flow: read_verilog -sv; hierarchy -top; proc; opt; wreduce; peepopt; alumacc; opt;
# memory -nomap (the coarse-grain part of `synth`, which narrows adders and multipliers before they
# are mapped, without its SAT-based `share`, which runs for many minutes on the pixel processor);
# memory_map; opt -full; async2sync; techmap; opt -fast;
# abc -fast -g AND,NAND,OR,NOR,XOR,XNOR,MUX (-fast: abc's default script spends minutes in SAT
# sweeping on each multiplier of the pixel lanes); opt_clean; dffunmap; stat -tech cmos. No
# flatten before stat: every module is reported on its own (its submodules in their own rows).
# async2sync and dffunmap only make every flop a plain $_DFF_P_ (an asynchronously reset flop
# counts as a flop and its reset multiplexer, an enable flop as a flop and its feedback
# multiplexer), which is what `stat -tech cmos` counts in whole transistors.
#
# Usage: tools/synth_report.sh [out_dir] [design...]   (default: build-rtl/synth, all designs)
# Writes out_dir/<design>.log (yosys), out_dir/<design>.txt (the table) and out_dir/report.txt (all
# tables); exits non-zero on any yosys error or an empty table.
# It never overwrites what it did not write: out_dir's marker .cig-synth-report lists the files it
# wrote there, and a file it would write that exists but is not listed is refused (exit 2, before
# any work), unless out_dir lies in a build folder of this source tree (generated files only). It
# deletes nothing. Refused too: the source tree outside its build*/ and out/ folders, a parent of
# it, $HOME and its parents, an existing non-folder (tools/lib/output_folder.sh).
set -euo pipefail
root=$(realpath "$(dirname "$0")/..")
# shellcheck disable=SC2034  # read by tools/lib/output_folder.sh
of_prog=synth_report
# shellcheck source-path=SCRIPTDIR source=lib/output_folder.sh
source "$root/tools/lib/output_folder.sh"
out=${1:-$root/build-rtl/synth}
shift || true
designs=("$@")
[ ${#designs[@]} -gt 0 ] || designs=(pe_mid pe_pixel raster ip_pe_57 ip_pe_64 ip_array_16)
command -v yosys >/dev/null || { echo "synth_report: yosys not found (tools/deps.sh installs it)" >&2; exit 2; }

# The RTL sources in compile order (the package first): the lists rtl/quadtree/qt_sources.cmake and
# rtl/invparam/ip_sources.cmake keep for every consumer, one file name per line between
# `set(<LIST>_NAMES` and `)`.
list_sources() {  # list_sources <folder of rtl/> <cmake file> <list name> <file prefix>
  local s
  s=$(sed -n "/^set($3/,/^)/s|^ *\($4_[a-z0-9_]*\.sv\)\$|$root/rtl/$1/\1|p" "$root/rtl/$1/$2")
  [ -n "$s" ] || { echo "synth_report: no sources in $root/rtl/$1/$2" >&2; exit 2; }
  echo $s
}
qt_sources=$(list_sources quadtree qt_sources.cmake CIG_RTL_SV_NAMES qt)
ip_sources=$(list_sources invparam ip_sources.cmake CIG_IP_RTL_SV_NAMES ip)

# top and -chparam arguments of a design.
design_args() {
  case "$1" in
    pe_mid)   echo "qt_pe -chparam N_LOG2 9 -chparam LEVEL 5" ;;
    pe_pixel) echo "qt_pe -chparam N_LOG2 9 -chparam LEVEL 9" ;;
    raster)   echo "qt_raster -chparam N_LOG2 4 -chparam TREE_LEVELS 2 -chparam G 6 -chparam PW 35 -chparam GW 20 -chparam LIGHT_COVERS 2 -chparam FOG_CODE_BITS 4" ;;
    ip_pe_57) echo "ip_pe" ;;   # W by design_pre: hierarchy -chparam on a top with submodules
    ip_pe_64) echo "ip_pe" ;;   # trips an assertion of yosys 0.23 (rtl/invparam/README.md)
    ip_array_16) echo "ip_array -chparam W 80 -chparam N_PP 16" ;;
    *) echo "synth_report: unknown design '$1' (pe_mid, pe_pixel, raster, ip_pe_57, ip_pe_64, ip_array_16)" >&2; exit 2 ;;
  esac
}

# Commands before `hierarchy` (parameters set on the module itself).
design_pre() {
  case "$1" in
    ip_pe_57) echo "chparam -set W 73 ip_pe" ;;   # the register width: seed W + 16 guard bits
    ip_pe_64) echo "chparam -set W 80 ip_pe" ;;
    *) echo "" ;;
  esac
}

# Every check before any work: the design names, the output folder and the files it will write
# there; the marker lists them before the first is written, so that a stopped run can be repeated.
for d in "${designs[@]}"; do design_args "$d" >/dev/null; done
of_check_place "$out" "$root" build
out=$(of_resolve "$out")
written=(report.txt)
for d in "${designs[@]}"; do
  for suffix in ys log stat.txt mapped.il ltp.ys ltp.txt ltp.log txt; do written+=("$d.$suffix"); done
done
of_check_written "$out" .cig-synth-report "$root" "${written[@]}"
mkdir -p "$out"
of_write_marker "$out" .cig-synth-report "cig-synth-report 1
written_by tools/synth_report.sh" \
  "$({ of_manifest "$out" .cig-synth-report; printf '%s\n' "${written[@]}"; } | sort -u)"
: > "$out/report.txt"
for d in "${designs[@]}"; do
  args=$(design_args "$d")
  top=${args%% *}
  case "$top" in ip_*) sources=$ip_sources ;; *) sources=$qt_sources ;; esac
  log="$out/$d.log"
  # Pass 1: synthesis, statistics, the mapped netlist, the modules' parameters.
  cat > "$out/$d.ys" <<EOF
read_verilog -sv $sources
$(design_pre "$d")
hierarchy -check -top $args
proc
opt_expr
opt_clean
opt -nodffe -nosdff
wreduce
peepopt
opt_clean
alumacc
opt
memory -nomap
opt_clean
memory_map
opt -full
async2sync
techmap
opt -fast
abc -fast -g AND,NAND,OR,NOR,XOR,XNOR,MUX
opt_clean
dffunmap
tee -o $out/$d.stat.txt stat -tech cmos
write_rtlil $out/$d.mapped.il
EOF
  yosys -q -l "$log" -s "$out/$d.ys" >/dev/null
  # Modules of the hierarchy (stat's "=== name ===" headers).
  mapfile -t modules < <(sed -n 's/^=== \(.*\) ===$/\1/p' "$out/$d.stat.txt" | grep -v '^design hierarchy$')
  # Pass 2: each module flattened on its own, its longest path.
  {
    echo "read_rtlil $out/$d.mapped.il"
    echo "design -save mapped"
    for m in "${modules[@]}"; do
      echo "design -load mapped"
      echo "hierarchy -top $m"
      echo "flatten"
      echo "tee -q -a $out/$d.ltp.txt ltp -noff"
    done
  } > "$out/$d.ltp.ys"
  : > "$out/$d.ltp.txt"
  yosys -q -l "$out/$d.ltp.log" -s "$out/$d.ltp.ys" >/dev/null
  # The table: module (its distinguishing parameters), instances in the design, cells,
  # transistors, longest path (cells).
  awk -v design="$d" -v top="$top" '
    FNR == 1 { file++ }
    # stat: per module cells and transistors; the hierarchy section: instance counts and totals.
    file == 1 && /^=== .* ===$/ { name = $0; sub(/^=== /, "", name); sub(/ ===$/, "", name); hier = (name == "design hierarchy"); next }
    file == 1 && /Number of cells:/ { if (hier) total_cells = $4; else cells[name] = $4; next }
    file == 1 && /Estimated number of transistors:/ { if (hier) total_tr = $5; else tr[name] = $5; next }
    # the hierarchy is a tree (indent 3 + 2 per depth) of counts per parent: multiply down it
    file == 1 && hier && NF == 2 && $2 ~ /^[0-9]+$/ && $1 !~ /:/ {
      depth = (match($0, /[^ ]/) - 4) / 2
      mult[depth] = $2 * (depth > 0 ? mult[depth - 1] : 1)
      inst[$1] += mult[depth]; next
    }
    # the own cells of a module: not its submodule instances (counted in their own rows)
    file == 1 && !hier && NF == 2 && $2 ~ /^[0-9]+$/ && $1 !~ /:/ && $1 !~ /^\$_/ { subcells[name] += $2; next }
    # ltp: "Longest topological path in <module> (length=<n>):"
    file == 2 && /^Longest topological path in/ { m = $5; l = $6; gsub(/[^0-9]/, "", l); ltp[m] = l; order[++n] = m; next }
    # mapped netlist: the parameters that tell instances of one module apart.
    file == 3 && /^module / { cur = $2; next }
    file == 3 && /^  parameter \\(LEVEL|ROUTE_BY_QUADRANT|UNIT|DI|DJ|N_LOG2|TREE_LEVELS|W|N_PP) / {
      p = $2; sub(/^\\/, "", p); v = $3; sub(/^1.1$/, "1", v); sub(/^1.0$/, "0", v)
      params[cur] = params[cur] (params[cur] == "" ? "" : ",") p "=" v; next
    }
    END {
      printf "design %s (top %s)\n", design, top
      printf "%-58s %6s %10s %13s %8s\n", "module", "inst", "cells", "transistors", "path"
      for (k = 1; k <= n; k++) {
        # a module with parameters is $paramod...\\<name>[\\<parameters>]: its name is the second part
        m = order[k]; np = split(m, part, "\\"); short = (m ~ /^\$paramod/) ? part[2] : part[np]
        i = (m in inst) ? inst[m] : 1
        label = short (params[m] != "" ? "(" params[m] ")" : "")
        rows[k] = sprintf("%-58s %6d %10d %13d %8d", label, i, cells[m] - subcells[m], tr[m], ltp[m])
        if (short == top) whole_path = ltp[m]
      }
      # rows by module name (insertion sort: a handful of rows)
      for (k = 2; k <= n; k++) { r = rows[k]; j = k - 1; while (j >= 1 && rows[j] > r) { rows[j + 1] = rows[j]; j-- } rows[j + 1] = r }
      for (k = 1; k <= n; k++) print rows[k]
      if (total_cells == "") { total_cells = cells[order[1]]; total_tr = tr[order[1]] }  # one module: no hierarchy section
      printf "%-58s %6s %10d %13d %8d\n", "TOTAL " top " (hierarchy)", "", total_cells, total_tr, whole_path
    }
  ' "$out/$d.stat.txt" "$out/$d.ltp.txt" "$out/$d.mapped.il" > "$out/$d.txt"
  cat "$out/$d.txt" >> "$out/report.txt"
  echo >> "$out/report.txt"
  # The design's total (the last count: the hierarchy's, or the only module's) must be whole.
  if ! grep -q '^TOTAL' "$out/$d.txt" || grep 'Estimated number of transistors' "$out/$d.stat.txt" | tail -1 | grep -q '+'; then
    echo "synth_report: $d: incomplete statistics (see $out/$d.stat.txt)" >&2
    exit 1
  fi
done
cat "$out/report.txt"
