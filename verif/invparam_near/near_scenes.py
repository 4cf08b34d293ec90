#!/usr/bin/env python3
"""The scenes of issue 29 (stage F near the eye), written into OUTDIR as cig scenes:

  hangar.json  a hangar (x in [-10, 10], y in [50, 60], z in [0, 8]) on a ground slab, one 60-degree
               channel, raster 128, the eye at (0, 0, h) looking along +y: frames 0..4 at
               h = 8.05, 8.002 (the roof's plane 2 mm below the eye), 7.999, 8.000001 (1 um),
               8.00000005 (50 nm: the setup decides the roof as through the eye)
  block.json   a block (x in [-10, 10], y in [10, 12], z in [0, 8]), view.near 0.001, the eye at
               (0, y, 2): frames 0..3 at y = 9.99, 9.995, 9.9995 (0.5 mm from the face, nearer
               than the near plane), 9.999999 (1 um)
  (no edge lies on a line of sample centres: x = y on the screen, for one, would make exact ties)
  crate.json   a 0.4 m crate 0.5 m in front of the eye (wholly nearer than view.near 1), a box
               that the near plane cuts, a wall behind them
  mixed.json   polyhedra and an ordinary (non-polyhedron) ground quad: frame 0 looks at the
               polyhedra, frame 1 away from them (no polyhedron in view)

usage: near_scenes.py OUTDIR"""
import json
import os
import sys

BOX_POLYGONS = [[3, 2, 1, 0], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]


def box(name, lo, hi, colour, polyhedron=True, layer=0):
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    vertices = [[x0, y0, z0], [x1, y0, z0], [x1, y1, z0], [x0, y1, z0],
                [x0, y0, z1], [x1, y0, z1], [x1, y1, z1], [x0, y1, z1]]
    sub = {"name": name, "crease_angle": 0, "colour": colour, "vertices": vertices,
           "polygons": [{"indices": p} for p in BOX_POLYGONS]}
    obj = {"name": name, "position": [0, 0, 0], "subobjects": [sub]}
    if polyhedron:
        obj["polyhedron"] = True
    if layer:
        obj["layer"] = layer
    return obj


def ground_slab():
    return box("ground", [-1000, -1000, -1], [1000, 1000, 0], [0.24, 0.32, 0.16], layer=-1)


def scene(name, objects, positions, near=1.0, headings=None):
    keyframes = [{"frame": k, "position": p, "heading": (headings or [0] * len(positions))[k], "pitch": 0, "roll": 0}
                 for k, p in enumerate(positions)]
    return {"format": "cig-scene", "version": 1, "name": name, "raster": 128, "view": {"near": near},
            "channels": [{"name": "front", "yaw": 0, "pitch": 0, "fov": 60}],
            "lighting": {"sun_direction": [-0.5, -0.7, 0.5], "sun_intensity": 0.6, "ambient": 0.3},
            "background": [0.55, 0.68, 0.85], "observer": {"keyframes": keyframes}, "objects": objects}


def scenes():
    hangar = box("hangar", [-10, 50, 0], [10, 60, 8], [0.7, 0.7, 0.75])
    block = box("block", [-10, 10, 0], [10, 12, 8], [0.8, 0.4, 0.3])
    crate = box("crate", [-0.2, 0.5, 1.8], [0.2, 0.9, 2.2], [0.6, 0.45, 0.2])  # wholly nearer than 1 m
    straddler = box("straddler", [0.31, 0.8, 1.7], [0.9, 1.4, 2.27], [0.3, 0.6, 0.3])  # cut by the near plane
    wall = box("wall", [-20, 10, 0], [20, 11, 10], [0.5, 0.5, 0.6])
    quad = {"name": "apron", "position": [0, 0, 0], "subobjects": [{
        "name": "apron", "colour": [0.3, 0.3, 0.3],
        "vertices": [[-50, -50, 0.01], [50, -50, 0.01], [50, 50, 0.01], [-50, 50, 0.01]],
        "polygons": [{"indices": [0, 1, 2, 3]}]}]}
    return {
        "hangar": scene("hangar", [ground_slab(), hangar],
                        [[0, 0, 8.05], [0, 0, 8.002], [0, 0, 7.999], [0, 0, 8.000001], [0, 0, 8.00000005]]),
        "block": scene("block", [ground_slab(), block],
                       [[0, 9.99, 2], [0, 9.995, 2], [0, 9.9995, 2], [0, 9.999999, 2]], near=0.001),
        "crate": scene("crate", [ground_slab(), crate, straddler, wall], [[0, 0, 2]], near=1.0),
        "mixed": scene("mixed", [quad, box("shed", [-5, 30, 0], [5, 40, 4], [0.7, 0.6, 0.5])],
                       [[0, 0, 2], [0, 0, 2]], headings=[0, 180]),
    }


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    for name, s in scenes().items():
        with open(os.path.join(out, name + ".json"), "w") as f:
            json.dump(s, f)


if __name__ == "__main__":
    main()
