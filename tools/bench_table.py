#!/usr/bin/env python3
"""Writes verif/bench/RESULTS.md (to stdout) from bench_llvmpipe's JSON output (tools/bench.sh):

    python3 tools/bench_table.py BENCH.json --machine TEXT --date TEXT --commit TEXT

Cases are named LIST/RENDERER (Google Benchmark appends /process_time/real_time); a case's time
is the median CPU time of its repetitions; a case that failed (an engine refusing the list) shows
its error. Tables: the CPU-time ratio engine / llvmpipe per list, the CPU times themselves, and
each image's PSNR against the float engine with the polygons the segment engine dropped, and
for the cases ENGINE@2 (two workers) the wall-time speed-up over the same engine on one."""
import argparse
import json
import math
import re
import statistics

ENGINES = ["float", "segment", "segment-double", "quadtree", "quadtree-double"]
TO_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}
COUNTERS = ("psnr_vs_float", "pixels_off", "polygons", "lights", "dropped")


def load_cases(path, parts=2):
    """The context, the lists, {(list, renderer): {"ms": median CPU ms, "wall_ms": median wall ms,
    "counters": {...}, "error": text}}. A case's name has `parts` fields before Google Benchmark's
    suffix: the last is the renderer, the others the list (curve/polys/1000/float: parts=4)."""
    with open(path) as f:
        doc = json.load(f)
    cases, lists = {}, []
    for b in doc["benchmarks"]:
        if b.get("run_type", "iteration") != "iteration":
            continue  # aggregates: the median is taken here, over the repetitions
        fields = b["run_name"].split("/")[:parts]
        name, renderer = "/".join(fields[:-1]), fields[-1]
        if name not in lists:
            lists.append(name)
        case = cases.setdefault((name, renderer), {"times": [], "wall": [], "counters": {}})
        if b.get("error_occurred"):
            case["error"] = b.get("error_message", "error")
            continue
        case["times"].append(b["cpu_time"] * TO_MS[b["time_unit"]])
        case["wall"].append(b["real_time"] * TO_MS[b["time_unit"]])
        case["counters"] = {k: b[k] for k in COUNTERS if k in b}
    for case in cases.values():
        case["ms"] = statistics.median(case["times"]) if case["times"] else None
        case["wall_ms"] = statistics.median(case["wall"]) if case["wall"] else None
    return doc.get("context", {}), sorted(lists, key=natural_key), cases  # random interleaving mixes them


def natural_key(name):
    """airfield_f0c1 < airfield_f1c0, depth2 < depth10: numbers compare as numbers."""
    return [int(t) if t.isdigit() else t for t in re.split(r"(\d+)", name)]


def table(header, rows):
    rule = "|" + "|".join("---:" if i else "---" for i in range(len(header))) + "|"
    lines = ["| " + " | ".join(header) + " |", rule]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return "\n".join(lines)


def ratio_rows(lists, cases):
    rows, logs = [], {e: [] for e in ENGINES}
    for name in lists:
        peer = cases.get((name, "llvmpipe"), {}).get("ms")
        counters = cases.get((name, "llvmpipe"), {}).get("counters", {})
        row = [name, "%d" % counters.get("polygons", 0), "%d" % counters.get("lights", 0)]
        row.append("%.1f" % peer if peer else "-")
        for e in ENGINES:
            ms = cases.get((name, e), {}).get("ms")
            if ms and peer:
                logs[e].append(math.log(ms / peer))
                row.append("%.2f" % (ms / peer))
            else:
                row.append("refused" if "error" in cases.get((name, e), {}) else "-")
        rows.append(row)
    mean = ["**geometric mean**", "", "", ""]
    mean += ["**%.2f**" % math.exp(statistics.mean(v)) if v else "-" for v in logs.values()]
    return rows + [mean]


def time_rows(lists, cases):
    rows = []
    for name in lists:
        row = [name]
        for r in ENGINES + ["llvmpipe"]:
            ms = cases.get((name, r), {}).get("ms")
            row.append("%.1f" % ms if ms else "-")
        rows.append(row)
    return rows


def speedup_rows(lists, cases, threads):
    """Lists with ENGINE@threads cases: the engine's one-worker wall time over its multi-worker one."""
    rows = []
    for name in lists:
        if not any((name, "%s@%d" % (e, threads)) in cases for e in ENGINES):
            continue
        row = [name]
        for e in ENGINES:
            one = cases.get((name, e), {}).get("wall_ms")
            many = cases.get((name, "%s@%d" % (e, threads)), {}).get("wall_ms")
            row.append("%.2f" % (one / many) if one and many else "-")
        rows.append(row)
    return rows


def psnr_rows(lists, cases):
    rows, lowest = [], {}
    for name in lists:
        row = [name]
        for r in ENGINES[1:] + ["llvmpipe"]:
            c = cases.get((name, r), {}).get("counters", {})
            if "psnr_vs_float" not in c:
                row.append("-")
                continue
            lowest[r] = min(lowest.get(r, 99.0), c["psnr_vs_float"])
            cell = "%.1f" % c["psnr_vs_float"]
            if c.get("dropped"):
                cell += " (%d dropped)" % c["dropped"]
            row.append(cell)
        rows.append(row)
    renderers = ENGINES[1:] + ["llvmpipe"]
    return rows + [["**lowest**"] + ["**%.1f**" % lowest[r] if r in lowest else "-" for r in renderers]]


def provenance_arguments(ap):
    """The options saying where and when the run was made (tools/bench.sh gives them)."""
    for option in ("--machine", "--date", "--commit"):
        ap.add_argument(option, required=True)


def print_provenance(a, context, cases):
    """Prints the machine, llvmpipe's version, the date and the commit; gives the repetitions."""
    print("* Machine: %s; %s" % (a.machine, context.get("llvmpipe", "llvmpipe")))
    print("* Date: %s; commit %s" % (a.date, a.commit))
    return max((len(c["times"]) for c in cases.values()), default=0)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("json")
    provenance_arguments(ap)
    a = ap.parse_args()
    context, lists, cases = load_cases(a.json)
    print("# cig raster engines against Mesa llvmpipe\n")
    print("Written by `tools/bench.sh` from `bench_llvmpipe` (verif/bench/bench_llvmpipe.cpp); do not edit.\n")
    reps = print_provenance(a, context, cases)
    print("* Time: CPU time of the process per frame, median of %d repetition(s), one thread each" % reps)
    print("  (llvmpipe with LP_NUM_THREADS=0); llvmpipe draws 4N x 4N (16 samples per pixel, as the engines),")
    print("  reads back and box-filters to N x N on the CPU, all timed; the lists' stages A and B are not timed.\n")
    print("## CPU time of each engine over llvmpipe's (above 1: llvmpipe is faster)\n")
    print(table(["list", "polygons", "lights", "llvmpipe ms"] + ENGINES, ratio_rows(lists, cases)) + "\n")
    print("## CPU time per frame (ms)\n")
    print(table(["list"] + ENGINES + ["llvmpipe"], time_rows(lists, cases)) + "\n")
    speedups = speedup_rows(lists, cases, 2)
    if speedups:
        print("## Two workers (`threads = 2`): wall time on one worker over wall time on two\n")
        print("Same bits on both (tested in verif/stress); the machine's two cores are both used.\n")
        print(table(["list"] + ENGINES, speedups) + "\n")
    print("## Image check: PSNR against the float engine (dB)\n")
    print("Polygons the segment engine dropped (overload protection, full frame memory) are noted.\n")
    print(table(["list"] + ENGINES[1:] + ["llvmpipe"], psnr_rows(lists, cases)))


if __name__ == "__main__":
    main()
