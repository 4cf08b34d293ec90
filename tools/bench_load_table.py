#!/usr/bin/env python3
"""Markdown section of bench_load's results: load time against input size.

Usage: tools/bench_load_table.py BENCH.json [--max-exponent X]

BENCH.json is Google Benchmark's JSON output of verif/bench/bench_load
(--benchmark_out=BENCH.json --benchmark_out_format=json). For each series (polygon lists through
load_polygon_list, the `cig polys` writer, scenes through load_scene) it prints a table of size,
MB, milliseconds, MB/s and peak memory, and the growth exponent b of time = a * size^b fitted by
least squares on log-log: 1 is linear, 2 quadratic. --max-exponent X exits with status 1 when a
series grows faster than size^X.
"""
import argparse
import json
import math
import sys

SERIES = [
    # name prefix, size column, title, whether the peak memory is that case's own (the first
    # series runs first in increasing size; later cases inherit the process's high-water mark)
    ("load/polygons:", "polygons", "Polygon list load (`cig raster`'s reader)", True),
    ("write/polygons:", "polygons", "Polygon list write (`cig polys`)", False),
    ("scene_load/triangles:", "triangles", "Scene load (one OBJ model, assimp + checks + priority compiler)", False),
]


def to_ms(value, unit):
    return value * {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[unit]


def cases(doc, prefix):
    """(size, run) of each case of a series; the mean when the run was repeated."""
    runs = {}
    for b in doc.get("benchmarks", []):
        name = b.get("run_name", b["name"])
        if not name.startswith(prefix) or b.get("error_occurred"):
            continue
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "mean":
            continue
        size = int(name[len(prefix):].split("/")[0])
        # A mean replaces the single iterations it summarises.
        if size not in runs or b.get("run_type") == "aggregate":
            runs[size] = b
    return sorted(runs.items())


def growth_exponent(points):
    """Least-squares slope of log(time) against log(size)."""
    xs = [math.log(n) for n, _ in points]
    ys = [math.log(t) for _, t in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx > 0 else float("nan")


def section(doc):
    lines, exponents = ["## Load time against input size", ""], {}
    ctx = doc.get("context", {})
    lines.append(f"bench_load, {ctx.get('date', '')}, {ctx.get('num_cpus', '?')} CPUs; "
                 "time is wall time of one load (or write), peak is the process's resident high-water mark.")
    lines.append("")
    for prefix, size_name, title, own_peak in SERIES:
        rows = cases(doc, prefix)
        if not rows:
            continue
        lines += [f"### {title}", ""]
        head = f"| {size_name} | MB | ms | MB/s | {size_name}/s |"
        rule = "|---:|---:|---:|---:|---:|"
        if own_peak:
            head += f" peak MB | peak bytes per {size_name[:-1]} |"
            rule += "---:|---:|"
        lines += [head, rule]
        points = []
        for size, b in rows:
            ms = to_ms(b["real_time"], b.get("time_unit", "ns"))
            points.append((size, ms))
            rate = b.get("polygons/s", b.get("triangles/s", 0.0))
            row = f"| {size:,} | {b.get('MB', 0):.1f} | {ms:.1f} | {b.get('MB/s', 0):.1f} | {rate:,.0f} |"
            if own_peak:
                row += f" {b.get('peak_MB', 0):.0f} | {b.get('peak_bytes/item', 0):.0f} |"
            lines.append(row)
        b = growth_exponent(points) if len(points) > 1 else float("nan")
        exponents[title] = b
        lines += ["", f"Growth exponent of time against {size_name} (least squares on log-log): **{b:.2f}** "
                  "(1 is linear, 2 quadratic).", ""]
    return "\n".join(lines), exponents


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("json", help="bench_load's Google Benchmark JSON output")
    p.add_argument("--max-exponent", type=float, help="fail when a series grows faster than size^X")
    a = p.parse_args()
    with open(a.json) as f:
        text, exponents = section(json.load(f))
    print(text)
    if not exponents:
        print("bench_load_table.py: no bench_load case in " + a.json, file=sys.stderr)
        return 1
    if a.max_exponent is not None:
        over = {t: b for t, b in exponents.items() if not b <= a.max_exponent}
        for t, b in over.items():
            print(f"bench_load_table.py: {t}: growth exponent {b:.2f} > {a.max_exponent}", file=sys.stderr)
        return 1 if over else 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
