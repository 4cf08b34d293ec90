#!/usr/bin/env python3
"""Models through assimp drawn right by the priority engines (issue 31): scenes/models.json (six
models of six formats from Debian's assimp-testmodels on a ground, a camera circling them).

  compare ENGINE FRAMES  `cig compare scenes/models.json --engine ENGINE --frames FRAMES` against the
                         float reference (z-buffer): PSNR >= 50 dB on every image and no pixel whose
                         polygon differs away from an edge; the same with --modeller-order (no
                         priority compiler) must fail both, or the check proves nothing.
  engines FRAMES         every engine renders the scene (exit 0); the bit-accurate priority engines
                         and their twins drop nothing; invparam, which draws only convex polyhedra,
                         says what it did not draw (report's dropped.polygons_not_drawn, a warning).
  cache                  a second load with the same --priority-cache reads every compiled tree from
                         it (cache_hits = compiled) and gives the same report figures.

usage: check_models.py CIG CASE WORKDIR [ARG...]"""
import json
import os
import shutil
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from cli_check import fail, run  # noqa: E402

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENE = os.path.join(SOURCE, "scenes", "models.json")
TESTMODELS = "/usr/share/assimp/models/AC/Wuson.ac"


def ok(cmd):
    r = run(cmd)
    if r.returncode != 0:
        fail(f"{' '.join(cmd)} exited {r.returncode}: {r.stderr[-2000:]}")
    return r


def compare(cig, work, engine, frames, extra):
    report = os.path.join(work, f"compare_{engine}{'_'.join(extra)}.json")
    ok([cig, "compare", SCENE, "--engine", engine, "--frames", frames, "--report", report,
        "--priority-cache", os.path.join(work, "cache")] + extra)
    with open(report) as f:
        return json.load(f)


def case_compare(cig, work, engine, frames):
    r = compare(cig, work, engine, frames, [])
    low = [(row["frame"], row["psnr"]) for row in r["rows"] if row["psnr"] < 50]
    if low:
        fail(f"{engine}: images below 50 dB against the float reference: {low}")
    if r["ids_differ_off_edges"] != 0:
        fail(f"{engine}: {r['ids_differ_off_edges']} pixels show another polygon away from any edge")
    before = compare(cig, work, engine, frames, ["--modeller-order"])
    if before["psnr_min"] >= 50 or before["ids_differ_off_edges"] == 0:
        fail(f"{engine} --modeller-order: lowest {before['psnr_min']:.2f} dB, "
             f"{before['ids_differ_off_edges']} pixels off edges: the scene does not need the compiler")
    print(f"{engine}: lowest {r['psnr_min']:.2f} dB, {r['ids_differ']} ids differ, 0 off edges; "
          f"modeller's order: lowest {before['psnr_min']:.2f} dB, {before['ids_differ_off_edges']} off edges")


def engine_draws_polyhedra_only(engines, name):
    entry = next(e for e in engines if e["name"] == name)
    return not entry["draws"]["polygons"]


def case_engines(cig, work, frames):
    engines = json.loads(ok([cig, "engines", "--json"]).stdout)["engines"]
    for name in [e["name"] for e in engines]:
        out = os.path.join(work, name)
        r = ok([cig, "render", SCENE, "--engine", name, "--frames", frames, "--out", out,
                "--priority-cache", os.path.join(work, "cache")])
        with open(os.path.join(out, "report.json")) as f:
            rep = json.load(f)
        formats = sorted({os.path.splitext(m["model"])[1].lower() for m in rep["models"]})
        if len(formats) < 6:
            fail(f"the scene holds models of {len(formats)} formats: {formats}")
        for fr in rep["frames"]:
            for ch in fr["channels"]:
                dropped = ch["raster"].get("dropped", {})
                lost = {k: v for k, v in dropped.items() if v}
                if engine_draws_polyhedra_only(engines, name):
                    if not lost.get("polygons_not_drawn") or "cannot draw" not in r.stderr:
                        fail(f"{name}: frame {fr['frame']}: models are not convex polyhedra, yet nothing is "
                             f"said: dropped {dropped}")
                elif lost:
                    fail(f"{name}: frame {fr['frame']}: dropped {lost}")
        print(f"{name}: {len(rep['frames'])} frames, formats {' '.join(formats)}")


def case_cache(cig, work):
    cache = os.path.join(work, "cache")
    reports = []
    for k in range(2):
        out = os.path.join(work, f"load{k}")
        ok([cig, "render", SCENE, "--engine", "float", "--frames", "0:0", "--out", out, "--priority-cache", cache])
        with open(os.path.join(out, "report.json")) as f:
            reports.append(json.load(f)["priority_compiler"])
    first, second = reports
    if first["compiled"] < 6 or first["cache_writes"] != first["compiled"]:
        fail(f"first load: {first}")
    if second["cache_hits"] != first["compiled"] or second["cache_writes"] != 0:
        fail(f"second load did not read every tree from the cache: {second}")
    for key in ("polygons_before", "polygons_after", "splits", "tree_nodes"):
        if first[key] != second[key]:
            fail(f"{key}: {first[key]} compiled, {second[key]} from the cache")
    print(f"compiled in {first['ms']:.1f} ms, read from the cache in {second['ms']:.1f} ms")


def main():
    if len(sys.argv) < 4:
        fail("usage: check_models.py CIG CASE WORKDIR [ARG...]")
    cig, case, work = sys.argv[1:4]
    if not os.path.exists(TESTMODELS):
        fail(f"{TESTMODELS} is missing: install the test dependencies (tools/deps.sh test)")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    if case == "compare":
        case_compare(cig, work, sys.argv[4], sys.argv[5])
    elif case == "engines":
        case_engines(cig, work, sys.argv[4])
    elif case == "cache":
        case_cache(cig, work)
    else:
        fail("unknown case " + case)


main()
