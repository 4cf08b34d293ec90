#!/usr/bin/env python3
"""Writes verif/bench/RESULTS.md (to stdout) from bench_llvmpipe's JSON output (tools/bench.sh):

    python3 tools/bench_table.py BENCH.json --machine TEXT --date TEXT --commit TEXT

Cases are named LIST/RENDERER (Google Benchmark appends /process_time/real_time); a case's time
is the median CPU time of its repetitions; a case that failed (an engine refusing the list) shows
its error. Tables: the CPU-time ratio engine / llvmpipe per list, the CPU times themselves, and
each image's PSNR against the float engine with the polygons the segment engine dropped."""
import argparse
import json
import math
import re
import statistics

ENGINES = ["float", "segment", "segment-double", "quadtree", "quadtree-double"]
TO_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}
COUNTERS = ("psnr_vs_float", "pixels_off", "polygons", "lights", "dropped")


def load_cases(path):
    """The context, the lists, {(list, renderer): {"ms": median CPU ms, "counters": {...}, "error": text}}."""
    with open(path) as f:
        doc = json.load(f)
    cases, lists = {}, []
    for b in doc["benchmarks"]:
        if b.get("run_type", "iteration") != "iteration":
            continue  # aggregates: the median is taken here, over the repetitions
        name, renderer = b["run_name"].split("/")[:2]
        if name not in lists:
            lists.append(name)
        case = cases.setdefault((name, renderer), {"times": [], "counters": {}})
        if b.get("error_occurred"):
            case["error"] = b.get("error_message", "error")
            continue
        case["times"].append(b["cpu_time"] * TO_MS[b["time_unit"]])
        case.setdefault("walls", []).append(b["real_time"] * TO_MS[b["time_unit"]])
        case["counters"] = {k: b[k] for k in COUNTERS if k in b}
    for case in cases.values():
        case["ms"] = statistics.median(case["times"]) if case["times"] else None
        case["wall_ms"] = statistics.median(case["walls"]) if case.get("walls") else None
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


def threads_rows(lists, cases):
    """The float engine's wall time on one and on two workers (strips of the image), and the ratio."""
    rows = []
    for name in lists:
        one = cases.get((name, "float"), {}).get("wall_ms")
        two = cases.get((name, "float-2threads"), {}).get("wall_ms")
        if one is None or two is None:
            continue
        rows.append([name, "%.1f" % one, "%.1f" % two, "%.2f" % (one / two)])
    return rows


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("json")
    ap.add_argument("--machine", required=True)
    ap.add_argument("--date", required=True)
    ap.add_argument("--commit", required=True)
    a = ap.parse_args()
    context, lists, cases = load_cases(a.json)
    reps = max((len(c["times"]) for c in cases.values()), default=0)
    print("# cig raster engines against Mesa llvmpipe\n")
    print("Written by `tools/bench.sh` from `bench_llvmpipe` (verif/bench/bench_llvmpipe.cpp); do not edit.\n")
    print("* Machine: %s; %s" % (a.machine, context.get("llvmpipe", "llvmpipe")))
    print("* Date: %s; commit %s" % (a.date, a.commit))
    print("* Time: CPU time of the process per frame, median of %d repetition(s), one thread each" % reps)
    print("  (llvmpipe with LP_NUM_THREADS=0); llvmpipe draws 4N x 4N (16 samples per pixel, as the engines),")
    print("  reads back and box-filters to N x N on the CPU, all timed; the lists' stages A and B are not timed.\n")
    print("## CPU time of each engine over llvmpipe's (above 1: llvmpipe is faster)\n")
    print(table(["list", "polygons", "lights", "llvmpipe ms"] + ENGINES, ratio_rows(lists, cases)) + "\n")
    print("## CPU time per frame (ms)\n")
    print(table(["list"] + ENGINES + ["llvmpipe"], time_rows(lists, cases)) + "\n")
    print("## Image check: PSNR against the float engine (dB)\n")
    print("Polygons the segment engine dropped (overload protection, full frame memory) are noted.\n")
    print(table(["list"] + ENGINES[1:] + ["llvmpipe"], psnr_rows(lists, cases)))
    rows = threads_rows(lists, cases)
    if rows:
        print("\n## Float engine on two threads (strips of the image, the same bits): wall time (ms)\n")
        print(table(["list", "1 thread", "2 threads", "speed-up"], rows))


if __name__ == "__main__":
    main()
