#!/usr/bin/env python3
"""Two cig binaries draw the same: images, id buffers and every counted figure of each raster engine.

  tools/same_output.py OLD_CIG NEW_CIG [--work DIR] [--quick] [--threads N,...]

For a speed change that must keep every bit and cycle (docs/verification.md): both binaries render
the same inputs (scenes through stages A and B, polygon lists, stress lists) with every raster
engine and several architectures; the new one also on each worker count of --threads. The PNGs and
the CIGIDS1 id buffers must be byte-identical, and the reports' raster sections equal once the
figures that are times (keys ending in `ms`, `per_second`, `_s`) and the worker count are set
aside: cycle counts, windows, samples and drops included. Exit 0 when all agree, 1 otherwise (each
difference named); 2 for a usage error. Writes only under --work (default a new temporary folder).
"""
import argparse
import filecmp
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ENGINES = [
    ("float", []),
    ("segment", []),
    ("segment-double", []),
    ("quadtree", []),
    ("quadtree-9p", ["--engine", "quadtree", "--arch", "9p"]),
    ("quadtree-7p2t-bbox", ["--engine", "quadtree", "--arch", "7p2t", "--start-window", "bbox"]),
    ("quadtree-nomasks", ["--engine", "quadtree", "--masks", "off"]),
    ("quadtree-double", []),
    ("invparam", []),
]
STRESS = ["slivers", "screen-edges", "depths", "intensities", "decals", "fans"]


def inputs(work, old, quick):
    """(name, kind, path, extra args): scenes render through the manager, lists through raster."""
    s = lambda p: os.path.join(ROOT, p)
    out = [
        ("airfield", "scene", s("scenes/airfield.json"), ["--frames", "0:0" if quick else "0:1"]),
        ("hut", "scene", s("scenes/small/hut.json"), ["--frames", "0:3"]),
        ("papi", "scene", s("scenes/small/papi.json"), []),
        ("mixed", "scene", s("scenes/small/mixed.json"), []),
        ("overlap", "list", s("scenes/small/overlap.polys.json"), []),
        ("depth10", "list", s("scenes/stress/depth10.polys.json"), []),
        ("overload", "list", s("scenes/stress/overload.polys.json"), []),
    ]
    if not quick:
        out.append(("bison_spider", "scene", s("scenes/small/bison_spider.json"), []))
    for cls in STRESS[:2] if quick else STRESS:
        path = os.path.join(work, "lists", cls + ".polys.json")
        if not os.path.exists(path):
            os.makedirs(os.path.dirname(path), exist_ok=True)
            subprocess.run([old, "stress", cls, "--seed", "7", "--out", path], check=True, capture_output=True)
        out.append(("stress_" + cls, "list", path, []))
    return out


def timeless(value):
    """The report without its times and worker counts."""
    if isinstance(value, dict):
        return {k: timeless(v) for k, v in value.items()
                if not (k.endswith("ms") or k.endswith("per_second") or k.endswith("_s") or k == "threads")}
    if isinstance(value, list):
        return [timeless(v) for v in value]
    return value


def raster_sections(report_path, kind):
    report = json.load(open(report_path))
    if kind == "list":
        return timeless({k: v for k, v in report.items() if k not in ("provenance", "command", "input")})
    return [[timeless(c.get("raster")) for c in f["channels"]] for f in report["frames"]]


def run(cig, kind, path, extra, engine_args, threads, out):
    os.makedirs(out, exist_ok=True)
    if kind == "scene":
        cmd = [cig, "render", path, "--out", out, "--ids", "--threads", str(threads)] + extra + engine_args
    else:
        cmd = [cig, "raster", path, "--out", os.path.join(out, "raster.png"), "--ids",
               os.path.join(out, "raster.ids"), "--report", os.path.join(out, "report.json")] + engine_args
    r = subprocess.run(cmd, capture_output=True, text=True)
    return r.returncode, r.stderr.strip().splitlines()[-1:] if r.returncode else []


def compare_dirs(a, b, kind):
    diffs = []
    files = sorted(f for f in os.listdir(a) if f.endswith(".png") or f.endswith(".ids"))
    if not files:
        diffs.append("no images written")
    for f in files:
        if not os.path.exists(os.path.join(b, f)):
            diffs.append(f + " missing")
        elif not filecmp.cmp(os.path.join(a, f), os.path.join(b, f), shallow=False):
            diffs.append(f + " differs")
    ra, rb = raster_sections(os.path.join(a, "report.json"), kind), raster_sections(os.path.join(b, "report.json"), kind)
    if ra != rb:
        diffs.append("report figures differ: " + first_difference(ra, rb))
    return diffs


def first_difference(a, b, where=""):
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            if a.get(k) != b.get(k):
                return first_difference(a.get(k), b.get(k), where + "." + k)
    if isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        for i, (x, y) in enumerate(zip(a, b)):
            if x != y:
                return first_difference(x, y, "%s[%d]" % (where, i))
    return "%s: %s != %s" % (where or "top", json.dumps(a)[:120], json.dumps(b)[:120])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--work")
    ap.add_argument("--quick", action="store_true", help="fewer inputs (about a third of the time)")
    ap.add_argument("--threads", default="1,2,4", help="worker counts the new binary runs (default 1,2,4)")
    args = ap.parse_args()
    threads = [int(t) for t in args.threads.split(",")]
    for b in (args.old, args.new):
        if not os.access(b, os.X_OK):
            print("same_output: %s: not an executable" % b, file=sys.stderr)
            return 2
    work = args.work or tempfile.mkdtemp(prefix="same_output.")
    failures, cases = [], 0
    for name, kind, path, extra in inputs(work, args.old, args.quick):
        for label, eargs in ENGINES:
            eargs = eargs or ["--engine", label]
            ref = os.path.join(work, "old", name, label)
            rc, err = run(args.old, kind, path, extra, eargs, 1, ref)
            for t in threads if kind == "scene" else [1]:
                cases += 1
                new = os.path.join(work, "new", name, label, str(t))
                rc2, err2 = run(args.new, kind, path, extra, eargs, t, new)
                if rc != rc2:
                    failures.append("%s %s threads %d: exit %d, was %d %s" % (name, label, t, rc2, rc, err2 or err))
                    continue
                if rc != 0:
                    continue  # refused by both: the same refusal is agreement
                for d in compare_dirs(ref, new, kind):
                    failures.append("%s %s threads %d: %s" % (name, label, t, d))
        print("same_output: %s done (%d cases, %d differences so far)" % (name, cases, len(failures)), flush=True)
    for f in failures:
        print("DIFFERS " + f)
    print("same_output: %d cases, %d differences (work: %s)" % (cases, len(failures), work))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
