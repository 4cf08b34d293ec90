#!/usr/bin/env python3
"""What an engine cannot draw is said (issue 28, deliverable 3), `cig engines` lists every engine,
and long commands show progress one line per step when stderr is not a terminal (deliverable 6).

On scenes/small/mixed.json (one convex polyhedron among ordinary objects and light points) the
invparam engine exits 0 and every command that renders it (render, compare, sweep) prints exactly
one warning line per image, naming the count of polygons it did not draw, which equals the
report's dropped.polygons_not_drawn; the float engine prints none; `cig raster` refuses stage F (a
polygon list has no polyhedra). With stderr a file, wordlength and compare print one progress
line per step and no carriage return.

usage: check_engine_drops.py CIG CASE WORKDIR
  (CASE: render, compare, sweep, raster, engines, engines_json, progress)"""
import json
import os
import re
import shutil
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from cli_check import fail, run  # noqa: E402

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MIXED = os.path.join(SOURCE, "scenes", "small", "mixed.json")
IMAGES = [(f, c) for f in (0, 1) for c in (0, 1)]  # --frames 0:1 x the scene's two channels
WARNING = re.compile(r"^cig: warning: (.*): the (\S+) engine cannot draw all of its input: "
                     r"(\d+) polygon\(s\) not drawn: not a face of a convex polyhedron .*?"
                     r"(?:; (\d+) light point\(s\) not drawn .*)?$")


def ok(cmd, r):
    if r.returncode != 0:
        fail(f"{' '.join(cmd)} exited {r.returncode}: {r.stderr}")


def warnings(stderr):
    """The drop warnings: image -> (polygons, light points); fails on a line of the wrong form."""
    found = {}
    for line in stderr.splitlines():
        if "warning" not in line:
            continue
        m = WARNING.match(line)
        if not m:
            fail(f"a warning line of another form: {line!r}")
        if m.group(1) in found:
            fail(f"two warnings for {m.group(1)}")
        found[m.group(1)] = (int(m.group(3)), int(m.group(4) or 0))
    return found


def render_counts(cig, work):
    """Per image name, the invparam report's (polygons_not_drawn, light_points_not_drawn)."""
    report = os.path.join(work, "report.json")
    cmd = [cig, "render", MIXED, "--frames", "0:1", "--engine", "invparam", "--out", work, "--report", report]
    r = run(cmd)
    ok(cmd, r)
    with open(report) as f:
        rep = json.load(f)
    counts = {}
    for fr in rep["frames"]:
        for ch in fr["channels"]:
            d = ch["raster"]["dropped"]
            counts[f"frame {fr['frame']} channel {ch['channel']}"] = (d["polygons_not_drawn"],
                                                                      d["light_points_not_drawn"])
    if sorted(counts) != sorted(f"frame {f} channel {c}" for f, c in IMAGES):
        fail(f"the report's images are {sorted(counts)}")
    if not all(p > 0 and l > 0 for p, l in counts.values()):
        fail(f"the mixed scene should leave polygons and light points undrawn in every image: {counts}")
    return counts, r.stderr


def case_render(cig, work):
    counts, stderr = render_counts(cig, work)
    got = warnings(stderr)
    if got != counts:
        fail(f"render warned {got}, the report counts {counts}")
    cmd = [cig, "render", MIXED, "--frames", "0:1", "--engine", "float", "--out", os.path.join(work, "float")]
    r = run(cmd)
    ok(cmd, r)
    if "warning" in r.stderr:
        fail(f"the float engine draws everything, yet: {r.stderr}")
    print("render: one warning per image:", got)


def case_compare(cig, work):
    counts, _ = render_counts(cig, os.path.join(work, "render"))
    cmd = [cig, "compare", MIXED, "--frames", "0:1", "--engine", "invparam"]
    r = run(cmd)
    ok(cmd, r)
    got = warnings(r.stderr)
    if got != counts:
        fail(f"compare warned {got}, render's report counts {counts}")
    print("compare: one warning per image:", got)


def case_sweep(cig, work):
    counts, _ = render_counts(cig, os.path.join(work, "render"))
    cmd = [cig, "sweep", MIXED, "--frames", "0:1", "--engine", "invparam", "--vary", "spp=4", "--repeat", "1"]
    r = run(cmd)
    ok(cmd, r)
    got = {k.replace("spp=4, ", ""): v for k, v in warnings(r.stderr).items()}
    if got != counts:
        fail(f"sweep warned {got}, render's report counts {counts}")
    print("sweep: one warning per image:", got)


def case_raster(cig, work):
    polys = os.path.join(work, "mixed.polys.json")
    ok(["polys"], run([cig, "polys", MIXED, "--frame", "0", "--channel", "0", "--out", polys]))
    out = os.path.join(work, "out")
    r = run([cig, "raster", polys, "--engine", "invparam", "--out", os.path.join(out, "x.png")])
    if r.returncode != 2 or "no polyhedron (a polygon list has none)" not in r.stderr or os.path.exists(out):
        fail(f"raster --engine invparam on a polygon list: exit {r.returncode}, {r.stderr!r}")
    cmd = [cig, "raster", polys, "--engine", "segment", "--out", os.path.join(out, "y.png")]
    r = run(cmd)
    ok(cmd, r)
    if "warning" in r.stderr:
        fail(f"the segment engine draws the list whole, yet: {r.stderr}")
    print("raster: stage F refused a polygon list;", r.stdout.strip())


def case_engines(cig, work):
    r = run([cig, "engines"])
    ok(["engines"], r)
    names = re.findall(r"^(\S+) \((?:bit-accurate|double)\): ", r.stdout, re.M)
    want = ["float", "segment", "segment-double", "quadtree", "quadtree-double", "invparam", "invparam-double"]
    if names != want:
        fail(f"cig engines lists {names}, not {want}")
    for text in ("bits=24..80", "default 64", "also --arch", "polygons_not_drawn", "polygons_overload",
                 "convex polyhedra", "rendering pipelines"):
        if text not in r.stdout:
            fail(f"cig engines does not say {text!r}")
    print(r.stdout.splitlines()[0])


def case_engines_json(cig, work):
    r = run([cig, "engines", "--json"])
    ok(["engines", "--json"], r)
    rep = json.loads(r.stdout)
    if list(rep)[0] != "provenance":
        fail("cig engines --json does not lead with its provenance")
    byname = {e["name"]: e for e in rep["engines"]}
    invparam = byname["invparam"]
    if [d["key"] for d in invparam["dropped"]] != ["polygons_not_drawn", "light_points_not_drawn",
                                                  "samples_on_undrawn_faces"]:
        fail(f"invparam's drop kinds: {invparam['dropped']}")
    if invparam["draws"]["light_points"] or not invparam["draws"]["polyhedra"]:
        fail(f"invparam draws {invparam['draws']}")
    # Every listed key at its default goes through a command (the same check as the parser's).
    for e in rep["engines"]:
        for o in e["options"]:
            if o["default"] == "":
                continue
            cmd = [cig, "render", MIXED, "--engine", e["name"], "--engine-opt", f"{o['key']}={o['default']}",
                   "--out", os.path.join(work, "defaults"), "--channel", "0"]
            r = run(cmd)
            ok(cmd, r)
    print("engines --json:", ", ".join(f"{n}: {len(e['options'])} keys" for n, e in byname.items()))


def progress_lines(stderr, label, steps):
    if "\r" in stderr:
        fail(f"{label} wrote a carriage return to a file: {stderr!r}")
    lines = [l for l in stderr.splitlines() if l.startswith(label + ": ")]
    want = [f"{label}: {k}/{steps} " for k in range(1, steps + 1)]
    if len(lines) != steps or not all(l.startswith(w) for l, w in zip(lines, want)):
        fail(f"{label}: expected one line per step ({steps}), got {lines}")
    return lines


def case_progress(cig, work):
    cmd = [cig, "wordlength", "--ranges", "1000,2000", "--bits", "40:41", "--views", "2", "--lattice", "16"]
    r = run(cmd)
    ok(cmd, r)
    lines = progress_lines(r.stderr, "cig wordlength", 4)
    cmd = [cig, "compare", MIXED, "--frames", "0:1", "--engine", "quadtree"]
    r = run(cmd)
    ok(cmd, r)
    lines += progress_lines(r.stderr, "cig compare", 4)
    print("\n".join(lines))


def main():
    cig, case, work = sys.argv[1], sys.argv[2], sys.argv[3]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    cases = {"render": case_render, "compare": case_compare, "sweep": case_sweep, "raster": case_raster,
             "engines": case_engines, "engines_json": case_engines_json, "progress": case_progress}
    if case not in cases:
        fail("unknown case " + case)
    cases[case](cig, work)


if __name__ == "__main__":
    main()
