#!/usr/bin/env python3
"""Instructions per image of every raster engine, an older cig against a newer one (callgrind).

  tools/bench_instructions.py OLD_CIG NEW_CIG [--work DIR] [--old-label TEXT] [--new-label TEXT]

The time-free half of the benchmark (tools/bench.sh --instructions=OLD_CIG runs it and writes the
section "instructions" of verif/bench/RESULTS.md): each binary rasterises the same polygon lists
with `cig raster` under `valgrind --tool=callgrind`, collecting only inside RasterEngine::render
(the engine proper: not the list's load nor the PNG write), and the table gives both counts and
their ratio. Instruction counts do not depend on the machine's load, so a change is judged by them
where timings are noisy. Lists: the centre channel of airfield frame 0 (written by NEW_CIG's
`cig polys`) and scenes/stress/depth10.polys.json. Prints the markdown section; exit 2 on a usage
error, 1 when a run fails."""
import argparse
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ENGINES = ["float", "segment", "segment-double", "quadtree", "quadtree-double"]
COLLECTED = re.compile(r"Collected : (\d+)")


def instructions(cig, polys, engine, work):
    out = os.path.join(work, "out.png")
    cmd = ["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null",
           "--toggle-collect=cig::RasterEngine::render(*", cig, "raster", polys, "--engine", engine, "--out", out]
    r = subprocess.run(cmd, capture_output=True, text=True)
    m = COLLECTED.search(r.stderr)
    if r.returncode != 0 or not m:
        sys.exit("bench_instructions: %s failed (exit %d): %s" % (" ".join(cmd), r.returncode, r.stderr[-400:]))
    return int(m.group(1))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--work")
    ap.add_argument("--old-label", default="before")
    ap.add_argument("--new-label", default="after")
    a = ap.parse_args()
    for b in (a.old, a.new):
        if not os.access(b, os.X_OK):
            print("bench_instructions: %s: not an executable" % b, file=sys.stderr)
            return 2
    work = a.work or tempfile.mkdtemp(prefix="bench_instructions.")
    airfield = os.path.join(work, "airfield_f0c1.polys.json")
    subprocess.run([a.new, "polys", os.path.join(ROOT, "scenes/airfield.json"), "--frame", "0", "--channel", "1",
                    "--out", airfield], check=True, capture_output=True)
    lists = [("airfield_f0c1", airfield), ("depth10", os.path.join(ROOT, "scenes/stress/depth10.polys.json"))]
    print("## Instructions per image, %s against %s\n" % (a.new_label, a.old_label))
    print("callgrind, instructions inside `RasterEngine::render` of `cig raster LIST --engine E` (every worker's "
          "counted; the load and the PNG write left out); millions. %s: `%s`; %s: `%s`.\n"
          % (a.old_label, a.old, a.new_label, a.new))
    print("| list | engine | %s (M) | %s (M) | %s / %s |" % (a.old_label, a.new_label, a.new_label, a.old_label))
    print("|---|---|---:|---:|---:|")
    for name, path in lists:
        for engine in ENGINES:
            old, new = instructions(a.old, path, engine, work), instructions(a.new, path, engine, work)
            print("| %s | %s | %.1f | %.1f | %.2f |" % (name, engine, old / 1e6, new / 1e6, new / old), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
