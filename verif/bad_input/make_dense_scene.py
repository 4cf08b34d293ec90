#!/usr/bin/env python3
"""Writes a scene whose first frame holds more polygons than a 16-bit polygon id counts: a 275 x 275
grid of 0.1 m quads (75,625 polygons), seen from 30 m straight above in frame 1; frame 0 looks
straight up and sees nothing. `cig render --frames 0:1` must refuse it before writing frame 0
(check_capacity.cmake). Usage: make_dense_scene.py OUT.json"""
import json
import sys

N = 275
vertices = [[i * 0.1 - N * 0.05, j * 0.1, 0] for j in range(N + 1) for i in range(N + 1)]
polygons = [{"indices": [j * (N + 1) + i, j * (N + 1) + i + 1, (j + 1) * (N + 1) + i + 1, (j + 1) * (N + 1) + i]}
            for j in range(N) for i in range(N)]
up = {"position": [0, N * 0.05, 30], "pitch": 90}
down = {"position": [0, N * 0.05, 30], "pitch": -90}
scene = {"format": "cig-scene", "version": 1, "raster": 64, "channels": [{"fov": 90}],
         "observer": {"keyframes": [dict(frame=0, **up), dict(frame=1, **down)]},
         "objects": [{"subobjects": [{"vertices": vertices, "polygons": polygons}]}]}
with open(sys.argv[1], "w") as f:
    json.dump(scene, f)
