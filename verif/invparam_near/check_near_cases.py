#!/usr/bin/env python3
"""Issue 29's cases against the float reference and the rules (stage F near the eye).

usage: check_near_cases.py CIG SCENES_DIR WORK CASE    CASE: hangar | block | crate | mixed | refused | cosim

hangar, block, crate: `cig compare` of near_scenes.py's scenes, every frame, with invparam at 64 and
57 bits and invparam-double, one sample per pixel at the pixel's centre in both (the same ray, so a
pixel is one sample: no majority vote between engines): 0 pixels may show another polygon than the
float reference, which clips at the near plane. The scenes keep every sample away from a silhouette
by more than the kernel's derived bound, so float is exact on them.
mixed: polyhedra and an ordinary ground quad: both frames render (frame 1 sees no polyhedron: an
empty frame), the quad is counted as not drawn (polygons_not_drawn, a warning on stderr).
refused: commands stage F refuses exit 2 before writing anything: no output folder is left.
cosim: `cig cosim --processor invparam` of every scene and frame above, with input gaps and VT
stalls, at the RTL builds' (W, N_PP) = (64, 8) and (57, 16): 0 mismatches, 0 cycle mismatches."""
import json
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cli"))
from cli_check import fail, run  # noqa: E402

FRAMES = {"hangar": "0:4", "block": "0:3", "crate": "0:0"}
ENGINES = [["invparam"], ["invparam", "bits=57"], ["invparam-double"]]


def compare(cig, scene, frames, engine, work):
    report = os.path.join(work, "compare.json")
    cmd = [cig, "compare", scene, "--frames", frames, "--engine", engine[0], "--engine-opt", "spp=1",
           "--reference-spp", "1", "--report", report]
    for opt in engine[1:]:
        cmd += ["--engine-opt", opt]
    r = run(cmd)
    if r.returncode != 0:
        fail(f"{' '.join(cmd)}: exit {r.returncode}: {r.stderr}")
    with open(report) as f:
        return json.load(f)


def case_compare(cig, scenes, work, name):
    scene = os.path.join(scenes, name + ".json")
    for engine in ENGINES:
        rep = compare(cig, scene, FRAMES[name], engine, work)
        for row in rep["rows"]:
            print(f"{name} frame {row['frame']} {' '.join(engine)}: ids differ {row['ids_differ']}, "
                  f"PSNR {row['psnr']:.2f} dB")
            if row["ids_differ"] != 0:
                fail(f"{name} frame {row['frame']} with {' '.join(engine)}: {row['ids_differ']} pixels show another "
                     "polygon than the float reference")


def case_mixed(cig, scenes, work):
    out = os.path.join(work, "mixed")
    r = run([cig, "render", os.path.join(scenes, "mixed.json"), "--frames", "0:1", "--engine", "invparam",
             "--out", out])
    if r.returncode != 0:
        fail(f"render of the mixed scene: exit {r.returncode}: {r.stderr}")
    with open(os.path.join(out, "report.json")) as f:
        rep = json.load(f)
    frames = rep["frames"]
    if len(frames) != 2:
        fail(f"mixed: {len(frames)} frames in the report, expected 2")
    for fr in frames:
        eng = fr["channels"][0]["raster"]
        dropped = eng["dropped"]["polygons_not_drawn"]
        print(f"mixed frame {fr['frame']}: objects {eng['objects']}, samples hit {eng['samples_hit']}, "
              f"polygons_not_drawn {dropped}")
        if dropped != 1:
            fail(f"mixed frame {fr['frame']}: polygons_not_drawn {dropped}, expected 1 (the ground quad)")
    if frames[0]["channels"][0]["raster"]["samples_hit"] == 0 or frames[1]["channels"][0]["raster"]["objects"] != 0:
        fail("mixed: frame 0 must draw the shed, frame 1 see no polyhedron")
    if "polygon(s) not drawn" not in r.stderr:
        fail("mixed: no warning on stderr for the polygons not drawn: " + r.stderr)


def case_refused(cig, scenes, work):
    polys = os.path.join(work, "polys.json")
    r = run([cig, "polys", os.path.join(scenes, "crate.json"), "--frame", "0", "--channel", "0", "--out", polys])
    if r.returncode != 0:
        fail("cig polys: " + r.stderr)
    bad_near = os.path.join(work, "bad_near.json")
    with open(os.path.join(scenes, "crate.json")) as f:
        scene = json.load(f)
    scene["view"]["near"] = 0.0005
    with open(bad_near, "w") as f:
        json.dump(scene, f)
    airfield = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scenes", "airfield.json")
    cases = [
        (["render", airfield, "--engine", "invparam"], "this scene has none"),
        (["compare", airfield, "--engine", "invparam"], "this scene has none"),
        (["compare", polys, "--engine", "invparam"], "a polygon list has none"),
        (["render", bad_near, "--engine", "invparam"], "view.near"),
    ]
    raster_out = os.path.join(work, "refused_raster.png")  # cig raster writes one file
    cases.append((["raster", polys, "--engine", "invparam", "--report", raster_out + ".json"],
                  polys + ": polygons: engine 'invparam' draws convex polyhedra"))
    for k, (args, expect) in enumerate(cases):
        out = raster_out if args[0] == "raster" else os.path.join(work, f"refused{k}")
        r = run([cig] + args + ["--out", out])
        print(f"refused: cig {' '.join(os.path.basename(a) for a in args)}: exit {r.returncode}: "
              f"{r.stderr.strip().splitlines()[-1] if r.stderr.strip() else ''}")
        if r.returncode != 2 or expect not in r.stderr:
            fail(f"cig {' '.join(args)}: exit {r.returncode}, expected 2 naming '{expect}': {r.stderr}")
        for left in (out, raster_out + ".json"):
            if os.path.exists(left):
                fail(f"cig {' '.join(args)}: refused, yet left {left} behind")


def case_cosim(cig, scenes, work):
    for name, frames in list(FRAMES.items()) + [("mixed", "0:1")]:
        for bits, pps in ((64, 8), (57, 16)):
            report = os.path.join(work, f"{name}_{bits}.json")
            r = run([cig, "cosim", os.path.join(scenes, name + ".json"), "--processor", "invparam", "--frames", frames,
                     "--bits", str(bits), "--pps", str(pps), "--input-gaps", "10", "--vt-stalls", "20",
                     "--report", report])
            last = r.stdout.strip().splitlines()[-1] if r.stdout.strip() else ""
            print(f"cosim {name} W={bits} N_PP={pps}: exit {r.returncode}: {last}")
            if r.returncode != 0 or " 0 mismatches, 0 frame(s) with a cycle mismatch" not in last:
                fail(f"cosim {name} W={bits}: {r.stdout[-2000:]}{r.stderr}")


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    cig, scenes, work, case = sys.argv[1:]
    os.makedirs(work, exist_ok=True)
    if case in FRAMES:
        case_compare(cig, scenes, work, case)
    elif case == "mixed":
        case_mixed(cig, scenes, work)
    elif case == "refused":
        case_refused(cig, scenes, work)
    elif case == "cosim":
        case_cosim(cig, scenes, work)
    else:
        sys.exit(__doc__)
    print("ok")


if __name__ == "__main__":
    main()
