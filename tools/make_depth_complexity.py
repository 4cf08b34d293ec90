#!/usr/bin/env python3
"""Writes scenes/stress/depth10.polys.json: a cig-polys list of depth complexity 10 for the
quadtree engine's priority masks (SPEC E, seed 004 eq. 11-16).

Ten depth slabs, nearest first; each slab holds opaque rotated rectangles at random positions
whose areas add up to one screen (so the total polygon area is ten screens), and a full-screen
quad closes the list at the back. Polygons are listed front to back (the priority order a
recursive-subdivision engine with masks needs); within a slab their depths do not overlap
either, so priority order and depth order agree everywhere (the float reference's z-buffer and
the priority masks must give the same image). Deterministic (seeded)."""
import json
import math
import random
import sys

RASTER = 512
SLABS = 10


def clip_to_screen(pts):
    """Sutherland-Hodgman against the four sides of [-1, 1]^2 (cig-polys lists are clipped)."""
    for axis in (0, 1):
        for sign in (-1.0, 1.0):
            out = []
            for k in range(len(pts)):
                a, b = pts[k], pts[(k + 1) % len(pts)]
                da, db = sign * a[axis] - 1.0, sign * b[axis] - 1.0  # inside when <= 0
                if da <= 0:
                    out.append(a)
                if (da <= 0) != (db <= 0):
                    t = da / (da - db)
                    out.append((a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])))
            pts = out
            if not pts:
                return pts
    return pts


def main(out):
    rng = random.Random(20261122)
    screen = 4.0  # area of [-1, 1]^2
    polys = []
    z = 10.0
    for slab in range(SLABS):
        area = 0.0
        while area < screen:
            w = rng.uniform(0.02, 0.25)
            h = rng.uniform(0.02, 0.25)
            cx = rng.uniform(-1.1, 1.1)
            cy = rng.uniform(-1.1, 1.1)
            a = rng.uniform(0, math.pi)
            ca, sa = math.cos(a), math.sin(a)
            corners = [(cx + u * ca - v * sa, cy + u * sa + v * ca) for (u, v) in ((-w, -h), (w, -h), (w, h), (-w, h))]
            i0, iu, iv = rng.uniform(0.3, 0.6), rng.uniform(0.0, 0.2), rng.uniform(0.0, 0.2)
            pts = clip_to_screen(corners)
            if len(pts) < 3:
                continue
            # Gouraud intensity: a plane in the rectangle's own coordinates (a flat shaded face
            # lit at a slant), evaluated at each (clipped) vertex.
            verts = []
            for (x, y) in pts:
                u = ((x - cx) * ca + (y - cy) * sa) / (2 * w) + 0.5
                v = (-(x - cx) * sa + (y - cy) * ca) / (2 * h) + 0.5
                i = i0 + iu * u + iv * v
                verts.append([round(min(1.0, max(-1.0, x)), 6), round(min(1.0, max(-1.0, y)), 6), round(z, 4), round(i, 4)])
            z += 0.01  # each polygon behind the previous one: depth order = list order
            colour = [round(rng.uniform(0.1, 1.0), 3) for _ in range(3)]
            polys.append({"colour": colour, "vertices": verts})
            area += 4 * w * h  # the unclipped area: slabs overfill the screen a little at its border
        z += 5.0
    back = [[-1, -1, z, 0.5], [1, -1, z, 0.5], [1, 1, z, 0.5], [-1, 1, z, 0.5]]
    polys.append({"colour": [0.2, 0.2, 0.25], "vertices": back})
    doc = {
        "format": "cig-polys",
        "version": 1,
        "raster": RASTER,
        "fog": {"colour": [0.5, 0.5, 0.55], "start": 30, "end": 200},
        "background": [0.05, 0.05, 0.1],
        "polygons": polys,
        "light_points": [],
    }
    with open(out, "w") as f:
        f.write('{\n  "format": "cig-polys",\n  "version": 1,\n  "raster": %d,\n' % RASTER)
        f.write('  "fog": %s,\n  "background": %s,\n  "polygons": [\n' % (json.dumps(doc["fog"]), json.dumps(doc["background"])))
        f.write(",\n".join("    " + json.dumps(p, separators=(", ", ": ")) for p in polys))
        f.write('\n  ],\n  "light_points": []\n}\n')
    print("%s: %d polygons in %d slabs" % (out, len(polys), SLABS), file=sys.stderr)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "scenes/stress/depth10.polys.json")
