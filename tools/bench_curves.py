#!/usr/bin/env python3
"""Writes the cost-curve section of verif/bench/RESULTS.md (to stdout) and its plots from the JSON
output of `bench_llvmpipe --curves` (tools/bench.sh --curves):

    python3 tools/bench_curves.py CURVES.json --plots DIR --machine TEXT --date TEXT --commit TEXT

Cases are named curve/AXIS/VALUE/RENDERER; a case's time is the median CPU time of its repetitions
(tools/bench_table.py's load_cases). Per axis: a table of the times, a log-log plot
DIR/curves_AXIS.png (gnuplot), and the growth exponent of each renderer, the least-squares slope of
log time against log size over the points it took (a refused point is left out; a point where the
engine dropped polygons is kept and named, its time being that of a partial image), beside
llvmpipe's over the same points: an engine grows faster than llvmpipe when its exponent exceeds
llvmpipe's by more than --margin (default 0.05, so that noise alone names no engine)."""
import argparse
import math
import os
import re
import subprocess
import sys

from bench_table import ENGINES, load_cases, natural_key, print_provenance, provenance_arguments, table

RENDERERS = ENGINES + ["llvmpipe"]
# The axes in the order bench_llvmpipe registers them: what the size is, what stays fixed.
AXES = {
    "polys": ("polygon count", "polygons", "small random triangles (circumradius 2 to 6 pixels), 512 lines, 16 spp"),
    "raster": ("raster size", "lines", "airfield frame 0, centre channel (4,241 polygons, 488 light points), 16 spp"),
    "spp": ("samples per pixel", "spp", "airfield frame 0, centre channel, 512 lines"),
    "depth": ("depth complexity", "depth", "the table's depth lists (rectangles in slabs), 512 lines, 16 spp"),
}


def curve_points(cases):
    """{axis: {value: {renderer: case}}} from the curve/AXIS/VALUE cases."""
    axes = {}
    for (name, renderer), case in cases.items():
        _, axis, value = name.split("/")
        axes.setdefault(axis, {}).setdefault(int(value), {})[renderer] = case
    return axes


def slope(points):
    """Least-squares slope of log time against log size over [(size, ms)], None below two sizes."""
    if len({x for x, _ in points}) < 2:
        return None
    xs = [math.log(x) for x, _ in points]
    ys = [math.log(y) for _, y in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def taken(points, renderer):
    """The (size, ms) points the renderer took, in size order."""
    return [(v, c[renderer]["ms"]) for v, c in sorted(points.items()) if c.get(renderer, {}).get("ms")]


def short_reason(error):
    """'refused: polygons: the segment engine takes at most 65536 polygons ... (why); frame 0 ...' ->
    ('refused', 'the segment engine takes at most 65536 polygons ...'): the kind and the rule."""
    kind, _, text = error.partition(": ")
    if kind not in ("refused", "n/a"):
        kind, text = "failed", error
    text = re.split(r" \(|; ", text, maxsplit=1)[0]
    return kind, re.sub(r"^[\w-]+: ", "", text)  # the InputError's option name


def cell(case):
    if case is None:
        return "-"
    if "error" in case:
        return short_reason(case["error"])[0]
    text = "%.1f" % case["ms"]
    dropped = case["counters"].get("dropped", 0)
    return text + (" (%d dropped)" % dropped if dropped else "")


def time_table(points, unit):
    rows = [["%d" % v] + [cell(points[v].get(r)) for r in RENDERERS] for v in sorted(points)]
    return table([unit] + RENDERERS, rows)


def short_number(v):
    """1000 -> 1k, 1000000 -> 1M: the plots' tick labels."""
    for scale, suffix in ((1000000, "M"), (1000, "k")):
        if v >= scale and v % scale == 0:
            return "%d%s" % (v // scale, suffix)
    return "%d" % v


def reasons(points):
    """One line per reason a case failed, with the renderers and sizes it applies to."""
    by_reason = {}
    for v in sorted(points):
        for r in RENDERERS:
            case = points[v].get(r)
            if case and "error" in case:
                entry = by_reason.setdefault(short_reason(case["error"]), ({}, []))
                entry[0][r] = None
                if v not in entry[1]:
                    entry[1].append(v)
    return ["* %s: %s at %s: %s" % (kind, ", ".join(rs), ", ".join("%d" % v for v in vs), text)
            for (kind, text), (rs, vs) in by_reason.items()]


def fit_rows(points, margin):
    """Per renderer: its exponent, the range, llvmpipe's over the same points, the verdict; the
    engines that grow faster than llvmpipe; {renderer: exponent, in bold when faster}."""
    rows, faster, summary = [], [], {}
    for r in RENDERERS:
        pts = taken(points, r)
        k = slope(pts)
        summary[r] = "%.2f" % k if k is not None else "-"
        if k is None:
            rows.append([r, "-", "fewer than two points", "", ""])
            continue
        sizes = [v for v, _ in pts]
        span = "%d..%d (%d points)" % (sizes[0], sizes[-1], len(sizes))
        dropped = [v for v in sizes if points[v][r]["counters"].get("dropped")]
        if dropped:
            span += ", polygons dropped at " + ", ".join("%d" % v for v in dropped)
        if r == "llvmpipe":
            rows.append([r, "%.2f" % k, span, "", ""])
            continue
        peer = slope([p for p in taken(points, "llvmpipe") if p[0] in sizes])
        verdict = "-"
        if peer is not None:
            verdict = "**faster**" if k > peer + margin else "no"
            if k > peer + margin:
                faster.append("%s (%.2f against %.2f)" % (r, k, peer))
                summary[r] = "**%.2f**" % k
        rows.append([r, "%.2f" % k, span, "%.2f" % peer if peer is not None else "-", verdict])
    return rows, faster, summary


def plot(axis, points, path):
    """A log-log plot of time against size, one line per renderer (gnuplot, PNG)."""
    label, unit, _ = AXES.get(axis, (axis, axis, ""))
    tics = ", ".join("'%s' %d" % (short_number(v), v) for v in sorted(points))
    script = ["set terminal pngcairo size 900,540 font 'sans,10'", "set output '%s'" % path,
              "set logscale xy", "set grid", "set key outside right", "set xtics (%s)" % tics,
              "set xlabel '%s (%s)'" % (label, unit), "set ylabel 'CPU ms per frame'",
              "set title 'time against %s'" % label]
    plots = []
    for i, r in enumerate(RENDERERS):
        pts = taken(points, r)
        if not pts:
            continue
        script += ["$d%d << EOD" % i] + ["%d %g" % p for p in pts] + ["EOD"]
        width = 3 if r == "llvmpipe" else 1.5
        colour = " lc rgb 'black'" if r == "llvmpipe" else ""
        plots.append("$d%d using 1:2 with linespoints lw %g%s title '%s'" % (i, width, colour, r))
    script.append("plot " + ", ".join(plots))
    subprocess.run(["gnuplot"], input="\n".join(script) + "\n", text=True, check=True)


def axis_section(axis, points, plots, margin):
    """The axis's lines of RESULTS.md (its plot drawn) and its exponents (fit_rows)."""
    label, unit, fixed = AXES.get(axis, (axis, axis, ""))
    values = sorted(points)
    out = ["### Time against %s (%d to %d %s)\n" % (label, values[0], values[-1], unit), "Fixed: %s.\n" % fixed]
    out.append("CPU ms per frame:\n")
    out.append(time_table(points, unit) + "\n")
    out += reasons(points) + ([""] if reasons(points) else [])
    name = "curves_%s.png" % axis
    plot(axis, points, os.path.join(plots, name))
    out.append("![time against %s](%s)\n" % (label, name))
    rows, faster, summary = fit_rows(points, margin)
    out.append("Growth exponent: slope of log time against log %s, least squares over the points taken:\n" % unit)
    out.append(table(["renderer", "exponent", "points fitted", "llvmpipe over the same points", "grows faster"],
                     rows) + "\n")
    verdict = "grows faster than llvmpipe: " + ", ".join(faster) if faster else "no engine grows faster than llvmpipe"
    out.append("**%s: %s** (margin %.2f).\n" % (label, verdict, margin))
    return out, summary


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("json")
    ap.add_argument("--plots", required=True, help="folder of the PNG plots (RESULTS.md's)")
    provenance_arguments(ap)
    ap.add_argument("--margin", type=float, default=0.05)
    a = ap.parse_args()
    context, _, cases = load_cases(a.json, parts=4)
    axes = curve_points(cases)
    if not axes:
        sys.exit("bench_curves: no curve/ cases in %s" % a.json)
    print("## Cost curves: time against polygon count, raster size, samples per pixel and depth complexity\n")
    print("Written by `tools/bench.sh --curves` from `bench_llvmpipe --curves`.\n")
    reps = print_provenance(a, context, cases)
    print("* Time: CPU time of the process per frame, median of %d repetition(s), one thread each, every" % reps)
    print("  engine and llvmpipe in the same run. S x S samples per pixel: the engines' setting spp = S^2;")
    print("  llvmpipe draws SN x SN and box-filters S x S (1 spp: N x N, 4: 2N, 16: 4N, 64: 8N).\n")
    order = [x for x in AXES if x in axes] + sorted((x for x in axes if x not in AXES), key=natural_key)
    sections = [axis_section(axis, axes[axis], a.plots, a.margin) for axis in order]
    print("Growth exponents (each axis's section says the points fitted; in bold: faster than llvmpipe over")
    print("the same points by more than %.2f):\n" % a.margin)
    rows = [[r] + [summary[r] for _, summary in sections] for r in RENDERERS]
    print(table(["renderer"] + [AXES.get(x, (x, x))[1] for x in order], rows) + "\n")
    for lines, _ in sections:
        print("\n".join(lines))


if __name__ == "__main__":
    main()
