#!/usr/bin/env python3
"""`cig import flightgear` on real data (issue 32): Keflavik (BIKF) from Debian's
flightgear-data-base, fetched by tools/fetch_flightgear.sh (tools/test.sh runs it first).

  import WORKDIR   BIKF at 20 km: the runways' lengths and headings against an independent
                   computation from apt.dat's coordinates (Vincenty's inverse on WGS-84, in this
                   file); terrain, tiles, objects and every light type present; the laid-out
                   runway edge, centre line and touchdown zone lights each within 3 m of a light
                   TerraGear placed (ICAO Annex 14 lets edge lights stand up to 3 m outside the
                   edge and sets the touchdown zone's inner gap anywhere in 18-22.5 m: two layouts
                   that follow it from the same thresholds differ by less); the scene renders
                   as written (cig render exits 0 and draws light points).
  temporal WORKDIR `cig temporal` on the night approach within the sample lattice's bounds.
  refuse WORKDIR   an unknown airport, a missing data folder and an --out that cig import did not
                   write: exit 2, a message naming the file and the rule, nothing written or
                   replaced.

usage: check_flightgear.py CIG CASE WORKDIR"""
import gzip
import json
import math
import os
import shutil
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from cli_check import fail, run  # noqa: E402


def fg_root():
    if os.environ.get("CIG_FLIGHTGEAR_ROOT"):
        return os.environ["CIG_FLIGHTGEAR_ROOT"]
    cache = os.environ.get("CIG_FLIGHTGEAR_CACHE", os.path.expanduser("~/.cache/cig/flightgear"))
    return os.path.join(cache, "fgdata")


def vincenty(lat1, lon1, lat2, lon2):
    """Distance (m) and initial bearing (deg) on WGS-84: Vincenty's inverse formula (1975)."""
    a, f = 6378137.0, 1 / 298.257223563
    b = a * (1 - f)
    L = math.radians(lon2 - lon1)
    U1, U2 = math.atan((1 - f) * math.tan(math.radians(lat1))), math.atan((1 - f) * math.tan(math.radians(lat2)))
    lam = L
    for _ in range(200):
        sl, cl = math.sin(lam), math.cos(lam)
        ss = math.hypot(math.cos(U2) * sl, math.cos(U1) * math.sin(U2) - math.sin(U1) * math.cos(U2) * cl)
        cs = math.sin(U1) * math.sin(U2) + math.cos(U1) * math.cos(U2) * cl
        sig = math.atan2(ss, cs)
        sa = math.cos(U1) * math.cos(U2) * sl / ss
        c2a = 1 - sa * sa
        c2sm = cs - 2 * math.sin(U1) * math.sin(U2) / c2a
        C = f / 16 * c2a * (4 + f * (4 - 3 * c2a))
        prev, lam = lam, L + (1 - C) * f * sa * (sig + C * ss * (c2sm + C * cs * (-1 + 2 * c2sm * c2sm)))
        if abs(lam - prev) < 1e-13:
            break
    u2 = c2a * (a * a - b * b) / (b * b)
    A = 1 + u2 / 16384 * (4096 + u2 * (-768 + u2 * (320 - 175 * u2)))
    B = u2 / 1024 * (256 + u2 * (-128 + u2 * (74 - 47 * u2)))
    ds = B * ss * (c2sm + B / 4 * (cs * (-1 + 2 * c2sm * c2sm) - B / 6 * c2sm * (-3 + 4 * ss * ss) * (-3 + 4 * c2sm * c2sm)))
    bearing = math.degrees(math.atan2(math.cos(U2) * math.sin(lam), math.cos(U1) * math.sin(U2) - math.sin(U1) * math.cos(U2) * math.cos(lam)))
    return b * A * (sig - ds), bearing % 360


def apt_runways(icao):
    rows, inside = [], False
    with gzip.open(os.path.join(fg_root(), "Airports", "apt.dat.gz"), "rt", encoding="latin-1") as f:
        for line in f:
            w = line.split()
            if w and w[0] in ("1", "16", "17"):
                if inside:
                    break
                inside = len(w) > 4 and w[4] == icao
            elif inside and w and w[0] == "100":
                rows.append(w)
    return {f"{w[8]}/{w[17]}": vincenty(float(w[9]), float(w[10]), float(w[18]), float(w[19])) for w in rows}


def ok(cmd):
    r = run(cmd)
    if r.returncode != 0:
        fail(f"{' '.join(cmd)} exited {r.returncode}: {r.stderr[-2000:]}")
    return r


def case_import(cig, work):
    scene, report = os.path.join(work, "bikf.json"), os.path.join(work, "bikf_import.json")
    ok([cig, "import", "flightgear", "BIKF", "--radius-km", "20", "--out", scene, "--report", report, "--raster", "128"])
    with open(report) as f:
        st = json.load(f)
    truth = apt_runways("BIKF")
    got = {r["name"]: r for r in st["runways"]}
    if sorted(got) != sorted(truth):
        fail(f"runways {sorted(got)}, apt.dat has {sorted(truth)}")
    for name, (length, bearing) in truth.items():
        # The local frame's plane distorts lengths 2 km from its origin by (2 km / R)^2 / 2 = 5e-8, and
        # its north differs from the runway's meridian by dlon sin(lat) < 0.05 deg: 0.01 % and 0.1 deg.
        r = got[name]
        if abs(r["length_m"] - length) > 1e-4 * length or abs((r["heading_deg"] - bearing + 180) % 360 - 180) > 0.1:
            fail(f"runway {name}: {r['length_m']} m heading {r['heading_deg']}, Vincenty {length:.2f} m {bearing:.3f}")
    t = st["terrain"]
    if len(st["tiles"]) < 3 or t["triangles"] < 50000 or t["unknown_materials"]:
        fail(f"terrain: {len(st['tiles'])} tiles, {t['triangles']} triangles, unknown {t['unknown_materials']}")
    if st["objects"]["objects"] < 100:
        fail(f"only {st['objects']['objects']} objects placed")
    lp = st["light_points"]["by_type"]
    for kind in ("runway_edge", "threshold", "runway_end", "centreline", "touchdown_zone", "approach", "papi"):
        if lp.get(kind, 0) == 0:
            fail(f"no {kind} lights: {lp}")
    check = st["light_points"]["terragear_check"]["by_type"]
    for kind in ("runway_edge", "centreline", "touchdown_zone"):
        c = check[kind]
        if c["matched"] != c["lights"] or c["max_m"] > 3:
            fail(f"{kind}: {c['matched']} of {c['lights']} within 5 m of TerraGear's, largest {c['max_m']} m (bound 3 m)")
    frames = st["approach"]["frames"]
    out = os.path.join(work, "render")
    ok([cig, "render", scene, "--frame", str(frames - 1000), "--engine", "float", "--out", out])
    with open(os.path.join(out, "report.json")) as f:
        rep = json.load(f)
    drawn = sum(c["raster"]["light_points"] for c in rep["frames"][0]["channels"])
    if drawn < 100:
        fail(f"the rendered frame draws {drawn} light points")
    print(f"BIKF: {t['triangles']} terrain triangles, {st['objects']['objects']} objects, {sum(lp.values())} lights "
          f"(edge within {check['runway_edge']['max_m']} m of TerraGear's), frame {frames - 1000} draws {drawn} light points")


def case_temporal(cig, work):
    """Night approach, 10 frames 17 s before touchdown, no objects (terrain, runways, lights), 256
    lines: every engine's scintillation and crawl within the sample lattice's bounds (derived in
    cmodel/cli/temporal_study.cpp and docs/flightgear.md) at 4 and 16 samples a pixel, with
    lights and edge rows measured, the change between frames below the bound's double, and the plot
    written."""
    scene, report, plot = (os.path.join(work, n) for n in ("night.json", "temporal.json", "temporal.png"))
    ok([cig, "import", "flightgear", "BIKF", "--radius-km", "20", "--time", "night", "--no-objects", "--raster", "256",
        "--out", scene])
    ok([cig, "temporal", scene, "--frames", "12000:12009", "--engines", "float,segment,quadtree", "--spp", "4,16",
        "--report", report, "--plot", plot])
    with open(report) as f:
        rep = json.load(f)
    if len(rep["series"]) != 6 or not os.path.getsize(plot) > 1000:
        fail(f"{len(rep['series'])} series, plot {os.path.getsize(plot)} bytes")
    for s in rep["series"]:
        sc, cr, name = s["scintillation"], s["crawl"], f"{s['engine']} spp {s['spp']}"
        if sc["light_frames"] < 20 or cr["rows"] < 100:
            fail(f"{name}: {sc['light_frames']} light-frames, {cr['rows']} edge rows measured: too few to judge")
        if sc["bound_violations"] or cr["bound_violations"]:
            fail(f"{name}: {sc['bound_violations']} lights, {cr['bound_violations']} rows beyond the lattice's bounds")
        if cr["max_delta_px"] > 2 * cr["bound_px"]:
            fail(f"{name}: an edge row moved {cr['max_delta_px']} px between frames (bound {2 * cr['bound_px']})")
    print("; ".join(f"{s['engine']} spp {s['spp']}: scintillation rms change {s['scintillation']['rms_delta']:.3f}, "
                    f"crawl rms change {s['crawl']['rms_delta_px']:.3f} px" for s in rep["series"]))


def refused(cmd, words):
    r = run(cmd)
    if r.returncode != 2 or not all(w in r.stderr for w in words):
        fail(f"{' '.join(cmd)}: exit {r.returncode}, stderr {r.stderr!r}; wanted exit 2 naming {words}")


def case_refuse(cig, work):
    out = os.path.join(work, "x.json")
    refused([cig, "import", "flightgear", "ZZZZ", "--out", out], ["apt.dat.gz", "no airport 'ZZZZ'"])
    refused([cig, "import", "flightgear", "BIKF", "--out", out, "--fg-root", os.path.join(work, "nowhere")],
            ["apt.dat.gz", "not found"])
    if os.path.exists(out):
        fail(f"{out} written by a refused import")
    mine = os.path.join(work, "mine.json")
    with open(mine, "w") as f:
        f.write('{"format": "cig-scene", "version": 1}\n')
    refused([cig, "import", "flightgear", "BIKF", "--out", mine], [mine, "not written by cig import"])
    with open(mine) as f:
        if f.read() != '{"format": "cig-scene", "version": 1}\n':
            fail(f"{mine} changed")
    print("refused: unknown airport, missing data, a file cig import did not write")


def main():
    if len(sys.argv) != 4:
        fail(__doc__)
    cig, case, work = sys.argv[1:]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    {"import": case_import, "refuse": case_refuse, "temporal": case_temporal}[case](cig, work)


if __name__ == "__main__":
    main()
