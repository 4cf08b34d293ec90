#!/usr/bin/env python3
"""Generate `scenes/polyhedra.json`: convex polyhedra for stage F (seed 002), at 1 km to 100 km.

    python3 tools/make_polyhedra.py > scenes/polyhedra.json   (or: make_polyhedra.py OUT.json)

Standard library only, deterministic. Every object is a closed convex polyhedron
("polyhedron": true): a ground slab 60 km x 60 km x 1 m (layer -1), a wall 120 m x 8 m x 40 m
with a panel 40 m x 16 m x 1 mm on its face (the seed's precision case: the panel's front face
lies 1 mm in front of the wall's, layer 1 so that priority engines draw it first), hangars
(pentagonal prisms: walls and a gable roof), octagonal towers, boxes, square pyramids, triangular
prisms, and a crate from an OBJ model (scenes/models/crate.obj, triangulated: its coplanar
triangles merge into six faces). The observer flies straight at the panel from 100 km to 1 km
(frames 0:9; 100 km at frame 0, 10 km at frame 3), aimed at its centre, through three channels
of 30, 3 and 0.4 degrees (the narrow one makes the panel 29 pixels wide at 100 km).
"""
import json
import math
import sys


def orient_outward(vertices, faces):
    """Winds every face counter-clockwise seen from outside (the solid is convex)."""
    c = [sum(v[k] for v in vertices) / len(vertices) for k in range(3)]
    out = []
    for f in faces:
        n = [0.0, 0.0, 0.0]
        for i in range(len(f)):
            a, b = vertices[f[i]], vertices[f[(i + 1) % len(f)]]
            n[0] += (a[1] - b[1]) * (a[2] + b[2])
            n[1] += (a[2] - b[2]) * (a[0] + b[0])
            n[2] += (a[0] - b[0]) * (a[1] + b[1])
        fc = [sum(vertices[i][k] for i in f) / len(f) for k in range(3)]
        out.append(f if sum(n[k] * (fc[k] - c[k]) for k in range(3)) > 0 else f[::-1])
    return out


def extrude(profile, axis, lo, hi):
    """A prism: the convex 2D `profile` extruded along `axis` ('y' or 'z') from lo to hi."""
    def point(p, t):
        return [p[0], t, p[1]] if axis == "y" else [p[0], p[1], t]
    n = len(profile)
    vertices = [point(p, lo) for p in profile] + [point(p, hi) for p in profile]
    faces = [list(range(n)), list(range(n, 2 * n))]
    faces += [[i, (i + 1) % n, n + (i + 1) % n, n + i] for i in range(n)]
    return vertices, faces


def box(x0, x1, y0, y1, z0, z1):
    return extrude([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], "z", z0, z1)


def hangar(width, length, wall, ridge):
    w = width / 2
    return extrude([(-w, 0), (w, 0), (w, wall), (0, ridge), (-w, wall)], "y", -length / 2, length / 2)


def gable_prism(width, length, height):
    w = width / 2
    return extrude([(-w, 0), (w, 0), (0, height)], "y", -length / 2, length / 2)


def tower(radius, height):
    ring = [(radius * math.cos(math.pi * (2 * k + 1) / 8), radius * math.sin(math.pi * (2 * k + 1) / 8))
            for k in range(8)]
    return extrude([(round(x, 3), round(y, 3)) for x, y in ring], "z", 0, height)


def pyramid(base, height):
    b = base / 2
    vertices = [[-b, -b, 0], [b, -b, 0], [b, b, 0], [-b, b, 0], [0, 0, height]]
    return vertices, [[0, 1, 2, 3], [0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]


def solid(name, shape, colour, position, heading=0, layer=0):
    vertices, faces = shape
    obj = {"name": name, "polyhedron": True, "position": position}
    if heading:
        obj["heading"] = heading
    if layer:
        obj["layer"] = layer
    obj["subobjects"] = [{
        "name": name, "crease_angle": 0, "colour": colour, "vertices": vertices,
        "polygons": [{"indices": f} for f in orient_outward(vertices, faces)]}]
    return obj


def objects():
    concrete, steel, brick = [0.62, 0.60, 0.56], [0.55, 0.58, 0.62], [0.58, 0.34, 0.26]
    objs = [
        solid("ground", box(-30000, 30000, -30000, 30000, -1, 0), [0.24, 0.32, 0.16], [0, 0, 0], layer=-1),
        solid("wall", box(-60, 60, 0, 8, 0, 40), concrete, [0, 0, 0]),
        # Its back face lies on the wall's front face (y = 0), its front face 1 mm in front.
        solid("panel", box(-20, 20, -0.001, 0, 12, 28), [0.95, 0.45, 0.10], [0, 0, 0], layer=1),
        solid("hangar_west", hangar(50, 70, 12, 20), steel, [-220, 120, 0], heading=10),
        solid("hangar_east", hangar(60, 80, 14, 24), steel, [200, 150, 0], heading=-15),
        solid("hangar_north", hangar(40, 50, 10, 16), steel, [-40, 320, 0], heading=90),
        solid("tower_west", tower(6, 80), brick, [-120, 40, 0]),
        solid("tower_east", tower(5, 60), brick, [130, 60, 0]),
        solid("box_a", box(-15, 15, -10, 10, 0, 18), [0.70, 0.66, 0.50], [-150, -120, 0], heading=25),
        solid("box_b", box(-8, 8, -8, 8, 0, 8), [0.40, 0.45, 0.60], [110, -80, 0]),
        solid("box_c", box(-25, 25, -6, 6, 0, 6), [0.50, 0.50, 0.52], [0, 60, 0]),
        solid("pyramid_a", pyramid(40, 30), [0.80, 0.72, 0.45], [260, -60, 0], heading=20),
        solid("pyramid_b", pyramid(24, 20), [0.75, 0.68, 0.42], [-300, -20, 0]),
        solid("prism_a", gable_prism(20, 40, 10), [0.45, 0.30, 0.25], [-90, -200, 0], heading=60),
        solid("prism_b", gable_prism(16, 30, 9), [0.45, 0.30, 0.25], [90, 200, 0]),
    ]
    objs.append({"name": "crate", "polyhedron": True, "position": [160, -30, 0], "heading": 30,
                 "subobjects": [{"name": "crate", "obj": "models/crate.obj", "scale": 10, "crease_angle": 0,
                                 "colour": [0.55, 0.42, 0.25]}]})
    return objs


def keyframes():
    frames = []
    for frame, r in enumerate([100000, 60000, 30000, 10000, 6000, 4000, 2500, 1600, 1200, 1000]):
        height = 20 + 0.02 * r  # a 1.15 degree approach at the panel's centre (0, 0, 20)
        pitch = -math.degrees(math.atan2(height - 20, r))
        frames.append({"frame": frame, "position": [0, -r, height], "heading": 0, "pitch": round(pitch, 6),
                       "roll": 0})
    return frames


def main():
    scene = {
        "format": "cig-scene", "version": 1, "name": "polyhedra", "raster": 512,
        "view": {"near": 1.0},
        "channels": [{"name": "wide", "yaw": 0, "pitch": 0, "fov": 30},
                     {"name": "tele", "yaw": 0, "pitch": 0, "fov": 3},
                     {"name": "narrow", "yaw": 0, "pitch": 0, "fov": 0.4}],
        "lighting": {"sun_direction": [-0.5, -0.7, 0.5], "sun_intensity": 0.6, "ambient": 0.3},
        "background": [0.55, 0.68, 0.85],
        "observer": {"keyframes": keyframes()},
        "objects": objects(),
    }
    objs = scene.pop("objects")
    compact = dict(separators=(",", ":"))
    # One object per line, as the other generated scenes.
    text = json.dumps(scene, **compact)[:-1] + ',"objects":[\n' + ",\n".join(json.dumps(o, **compact) for o in objs)
    text += "\n]}\n"
    if len(sys.argv) > 1:
        with open(sys.argv[1], "w") as out:
            out.write(text)
    else:
        sys.stdout.write(text)
    print(f"polyhedra.json: {len(objs)} objects, {len(scene['observer']['keyframes'])} frames",
          file=sys.stderr)


if __name__ == "__main__":
    main()
