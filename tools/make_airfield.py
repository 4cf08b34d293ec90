#!/usr/bin/env python3
"""Generate the default cig-scene `scenes/airfield.json`: an airfield approach at dusk.

    python3 tools/make_airfield.py > scenes/airfield.json

Standard library only and deterministic (fixed seed, fixed iteration order): two runs give the
same bytes. A one-line summary (objects, polygons, light points, frames) goes to stderr.

Layout. Everything is modelled in a *runway frame* R: origin at the runway centre, +y along the
landing direction of runway 24 (true heading 240 deg), +x to the right of it, z up. Objects carry
heading 240 (plus their own turn), so their local coordinates are R-frame axes and all
axis-aligned geometry stays exactly planar after rounding. World position = rotation of R.

  * runway 24/06: 3000 m x 45 m (+ 7.5 m shoulders), threshold 24 at R y = -1500, markings for
    both ends (piano keys, designations, aiming point, touchdown zone, centreline, edge lines);
  * parallel taxiway 180 m left of the centreline, five connectors, an apron on its left with
    parked aircraft, terminal, control tower, three hangars, fire station, fuel farm, car park;
  * flat fields (150 m blocks around the airfield), a road across the approach, a village,
    forests; hills (triangulated heightfield, 300 m grid) from ~4 km out, up to ~500 m;
  * lights: runway edge, threshold/wing bars, runway end, approach lighting (centre barrettes,
    300 m crossbar, red side barrettes), PAPI, taxiway edges, floodlight masts, street lights,
    obstruction lights, aircraft navigation lights;
  * a self-lit sky dome (warm glow at the horizon and around the low sun in the west, dark
    blue-violet above) and a sun disc;
  * observer: straight-in approach along a 3 deg glide path aimed 300 m past the threshold, from
    3.2 km before the threshold at ~183 m to 20 m before it at ~17 m, starting 38 m left of the
    extended centreline and correcting onto it (small heading and roll changes). The default 150
    frames compress the ~45 s approach (25 Hz) into 6 s; `--frames N` stretches it.
"""

import argparse
import math
import random
import sys

SEED = 1967
RWY_HDG = 240.0               # true heading of runway 24 (landing direction, R-frame +y)
RWY_LEN, RWY_W, SHOULDER = 3000.0, 45.0, 7.5
THR = -RWY_LEN / 2            # threshold 24 (R-frame y)
AIM = THR + 300.0             # glide path aiming point / PAPI
GLIDE = 3.0
TWY_X, TWY_W = -180.0, 23.0
DY = -500.0                   # the terminal area lies between 0.35 and 1.25 km past threshold 24
APRON = (-500.0, TWY_X - TWY_W / 2, -650.0 + DY, 250.0 + DY)   # x0, x1, y0, y1
FLAT = (-3000.0, 3000.0, -7200.0, 3600.0)            # flat zone (R-frame), multiple of 600 m
BLOCK = 150.0                                         # ground block size in the flat zone
HILL_CELL = 300.0
HILL_BOX = (-13200.0, 13200.0, -9000.0, 15600.0)
DOME_C = (0.0, -2500.0)       # sky dome centre (R-frame)
TERRAIN_R = 14000.0           # hill cells beyond this distance from the dome centre are dropped
SUN_AZ, SUN_EL = 275.0, 5.0   # true azimuth / elevation of the sun (deg)
FOG = dict(colour=(0.50, 0.38, 0.33), start=1500.0, end=36000.0)
BACKGROUND = (0.09, 0.08, 0.21)


# ---------------------------------------------------------------------------------------------
# small vector helpers

def add(a, b): return (a[0] + b[0], a[1] + b[1], a[2] + b[2])
def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def mul(a, s): return (a[0] * s, a[1] * s, a[2] * s)
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
def norm(a):
    l = math.sqrt(dot(a, a))
    return (a[0] / l, a[1] / l, a[2] / l)


def newell(pts):
    n = [0.0, 0.0, 0.0]
    for i, p in enumerate(pts):
        q = pts[(i + 1) % len(pts)]
        n[0] += (p[1] - q[1]) * (p[2] + q[2])
        n[1] += (p[2] - q[2]) * (p[0] + q[0])
        n[2] += (p[0] - q[0]) * (p[1] + q[1])
    return tuple(n)


def centroid(pts):
    k = 1.0 / len(pts)
    return (sum(p[0] for p in pts) * k, sum(p[1] for p in pts) * k, sum(p[2] for p in pts) * k)


def r2w(x, y, z=0.0):
    """R-frame point to world (x east, y north)."""
    h = math.radians(RWY_HDG)
    return (x * math.cos(h) + y * math.sin(h), -x * math.sin(h) + y * math.cos(h), z)


def smoothstep(a, b, t):
    u = min(1.0, max(0.0, (t - a) / (b - a)))
    return u * u * (3 - 2 * u)


def ihash(*k):
    """Deterministic integer hash -> [0, 1)."""
    h = 2166136261
    for v in k:
        h ^= (int(v) & 0xFFFFFFFF)
        h = (h * 16777619) & 0xFFFFFFFF
        h ^= h >> 13
        h = (h * 1274126177) & 0xFFFFFFFF
    return (h & 0xFFFFFF) / float(0x1000000)


def jitter(c, amount, u):
    s = 1.0 + amount * (2.0 * u - 1.0)
    return tuple(min(1.0, max(0.0, v * s)) for v in c)


# ---------------------------------------------------------------------------------------------
# scene containers

class Sub:
    def __init__(self, name, colour=None, crease=None, protected=False):
        self.name, self.colour, self.crease, self.protected = name, colour, crease, protected
        self.verts, self.index, self.polys = [], {}, []

    def v(self, p):
        key = tuple(round(c, 4) + 0.0 for c in p)
        i = self.index.get(key)
        if i is None:
            i = self.index[key] = len(self.verts)
            self.verts.append(key)
        return i

    def face(self, pts, colour=None, intensity=None, facing=None):
        """Add a polygon; with `facing` the winding is fixed so that its normal points that way."""
        if facing is not None and dot(newell(pts), facing) < 0:
            pts = pts[::-1]
            if isinstance(intensity, list):
                intensity = intensity[::-1]
        idx = [self.v(p) for p in pts]
        self.polys.append((idx, colour, intensity))

    def solid(self, faces, colour=None, intensity=None, skip_down=False):
        """Convex solid given as a list of faces (point lists): each face is wound outwards."""
        allp = [p for f in faces for p in f]
        c = centroid(allp)
        for f in faces:
            n = newell(f)
            out = sub(centroid(f), c)
            if dot(n, out) < 0:
                n = mul(n, -1.0)
            if skip_down and n[2] < -0.999 * math.sqrt(dot(n, n)):
                continue
            self.face(f, colour, intensity, facing=out)

    def empty(self):
        return not self.polys


class Obj:
    def __init__(self, name, origin=(0.0, 0.0, 0.0), turn=0.0, pitch=0.0, roll=0.0, frame='R'):
        self.name, self.origin, self.turn, self.pitch, self.roll = name, origin, turn, pitch, roll
        self.frame = frame          # 'R': local axes are R-frame axes (turned by `turn`); 'W': world
        self.subs, self.lights, self.sphere = [], [], None

    def sub(self, *a, **k):
        s = Sub(*a, **k)
        self.subs.append(s)
        return s

    def light(self, p, colour, diameter=2.0, intensity=1.0):
        self.lights.append((p, colour, diameter, intensity))


OBJECTS = []


def new_obj(*a, **k):
    o = Obj(*a, **k)
    OBJECTS.append(o)
    return o


# ---------------------------------------------------------------------------------------------
# geometry builders (local coordinates)

def box_faces(x0, x1, y0, y1, z0, z1, bottom=True):
    c = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
         (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    f = [[c[0], c[1], c[5], c[4]], [c[1], c[2], c[6], c[5]], [c[2], c[3], c[7], c[6]],
         [c[3], c[0], c[4], c[7]], [c[4], c[5], c[6], c[7]]]
    if bottom:
        f.append([c[0], c[3], c[2], c[1]])
    return f


def loft_faces(ring_a, ring_b, caps=True):
    """Convex solid between two homothetic convex rings in parallel planes."""
    n = len(ring_a)
    f = [[ring_a[i], ring_a[(i + 1) % n], ring_b[(i + 1) % n], ring_b[i]] for i in range(n)]
    if caps:
        f += [list(ring_a), list(ring_b)]
    return f


def ngon_xz(cx, cz, r, y, n=8, phase=None, sx=1.0):
    """Regular n-gon in the plane y = const (for fuselages along y)."""
    if phase is None:
        phase = math.pi / n
    return [(cx + sx * r * math.cos(phase + 2 * math.pi * k / n), y,
             cz + r * math.sin(phase + 2 * math.pi * k / n)) for k in range(n)]


def ngon_xy(cx, cy, r, z, n=8, phase=None):
    if phase is None:
        phase = math.pi / n
    return [(cx + r * math.cos(phase + 2 * math.pi * k / n),
             cy + r * math.sin(phase + 2 * math.pi * k / n), z) for k in range(n)]


def slab_xy(poly2d, z0, z1):
    """Convex planform (x, y) extruded between z0 and z1."""
    return loft_faces([(x, y, z0) for x, y in poly2d], [(x, y, z1) for x, y in poly2d])


def slab_yz(poly2d, x0, x1):
    """Convex profile (y, z) extruded between x0 and x1."""
    return loft_faces([(x0, y, z) for y, z in poly2d], [(x1, y, z) for y, z in poly2d])


def quad_up(sub, x0, x1, y0, y1, z=0.0, colour=None, intensity=None):
    sub.face([(x0, y0, z), (x1, y0, z), (x1, y1, z), (x0, y1, z)], colour, intensity)


# ---------------------------------------------------------------------------------------------
# layout: paved areas (R-frame rectangles x0, x1, y0, y1) cut out of the ground

CONNECTORS = [-1470.0, -700.0, -60.0, 700.0, 1470.0]
ROAD_A_Y, ROAD_W = -3000.0, 8.0
ROAD_B_X = -660.0
CARPARK = (-760.0, -672.0, -420.0 + DY, -200.0 + DY)
VILLAGE = (700.0, 1500.0, -3560.0, -3040.0)


def paved_rects():
    r = []
    r.append(('runway', (-RWY_W / 2 - SHOULDER, RWY_W / 2 + SHOULDER, THR, -THR)))
    r.append(('taxiway', (TWY_X - TWY_W / 2, TWY_X + TWY_W / 2, THR - 20, -THR + 20)))
    for yc in CONNECTORS:
        r.append(('taxiway', (TWY_X + TWY_W / 2, -RWY_W / 2 - SHOULDER, yc - TWY_W / 2, yc + TWY_W / 2)))
    r.append(('apron', APRON))
    r.append(('road', (FLAT[0], FLAT[1], ROAD_A_Y - ROAD_W / 2, ROAD_A_Y + ROAD_W / 2)))
    r.append(('road', (ROAD_B_X - ROAD_W / 2, ROAD_B_X + ROAD_W / 2, ROAD_A_Y + ROAD_W / 2, 400.0 + DY)))
    r.append(('road', (1100.0 - ROAD_W / 2, 1100.0 + ROAD_W / 2, VILLAGE[2] - 300, ROAD_A_Y - ROAD_W / 2)))
    r.append(('road', (CARPARK[1], ROAD_B_X - ROAD_W / 2, -320.0 + DY, -300.0 + DY)))
    r.append(('carpark', CARPARK))
    return r


PAVED = paved_rects()


def in_rect(x, y, r, margin=0.0):
    return r[0] - margin <= x <= r[1] + margin and r[2] - margin <= y <= r[3] + margin


def on_paved(x, y, margin=0.0):
    return any(in_rect(x, y, r, margin) for _, r in PAVED)


# ---------------------------------------------------------------------------------------------
# terrain heights

def make_bumps(rng):
    bumps = []
    while len(bumps) < 90:
        x = rng.uniform(HILL_BOX[0], HILL_BOX[1])
        y = rng.uniform(HILL_BOX[2], HILL_BOX[3])
        d = rect_distance(x, y, FLAT)
        if d < 1500:
            continue
        s = rng.uniform(600, 2000)
        a = rng.uniform(60, 260) * min(1.0, 0.5 + d / 6000)
        # keep the western sky near the sun open: lower hills in that direction
        bumps.append((x, y, s, a))
    return bumps


def rect_distance(x, y, r):
    dx = max(r[0] - x, 0.0, x - r[1])
    dy = max(r[2] - y, 0.0, y - r[3])
    return math.hypot(dx, dy)


def height(x, y):
    d = rect_distance(x, y, FLAT)
    m = smoothstep(450.0, 3500.0, d)
    if m <= 0.0:
        return 0.0
    h = 0.0
    for bx, by, s, a in BUMPS:
        q = ((x - bx) ** 2 + (y - by) ** 2) / (s * s)
        if q < 12:
            h += a * math.exp(-q)
    # gentle long ridges
    h += 40 * (1 + math.sin(x / 1700.0 + 0.7) * math.cos(y / 2300.0 - 0.4))
    h = 520 * (1 - math.exp(-h / 420.0))      # soft ceiling
    return round(m * h, 1)


def hill_grid_z(ix, iy):
    key = (ix, iy)
    z = HCACHE.get(key)
    if z is None:
        z = HCACHE[key] = height(HILL_BOX[0] + ix * HILL_CELL, HILL_BOX[2] + iy * HILL_CELL)
    return z


def cell_diagonal(ix, iy):
    """True: split along a-c (x0y0-x1y1), else b-d."""
    za, zb = hill_grid_z(ix, iy), hill_grid_z(ix + 1, iy)
    zc, zd = hill_grid_z(ix + 1, iy + 1), hill_grid_z(ix, iy + 1)
    return abs(za - zc) <= abs(zb - zd)


def terrain_z(x, y):
    """Height of the triangulated terrain surface (0 in the flat zone)."""
    if in_rect(x, y, FLAT):
        return 0.0
    fx = (x - HILL_BOX[0]) / HILL_CELL
    fy = (y - HILL_BOX[2]) / HILL_CELL
    ix, iy = int(math.floor(fx)), int(math.floor(fy))
    u, v = fx - ix, fy - iy
    za, zb = hill_grid_z(ix, iy), hill_grid_z(ix + 1, iy)
    zc, zd = hill_grid_z(ix + 1, iy + 1), hill_grid_z(ix, iy + 1)
    if cell_diagonal(ix, iy):
        return za + u * (zb - za) + v * (zc - zb) if u >= v else za + u * (zc - zd) + v * (zd - za)
    return za + u * (zb - za) + v * (zd - za) if u + v <= 1 else \
        zc + (1 - u) * (zd - zc) + (1 - v) * (zb - zc)


# ---------------------------------------------------------------------------------------------
# colours (linear RGB albedo)

GRASS_AF = (0.30, 0.41, 0.19)
FIELDS = [(0.27, 0.39, 0.17), (0.21, 0.31, 0.13), (0.50, 0.42, 0.23), (0.36, 0.27, 0.17),
          (0.37, 0.39, 0.19), (0.55, 0.47, 0.30), (0.24, 0.35, 0.16), (0.42, 0.33, 0.20)]
FOREST = (0.13, 0.21, 0.10)
ASPHALT = (0.23, 0.23, 0.245)
SHOULDER_C = (0.30, 0.30, 0.30)
CONCRETE = (0.45, 0.45, 0.43)
PAINT_W = (0.92, 0.92, 0.90)
PAINT_Y = (0.90, 0.72, 0.15)
WARM_WINDOW = (1.0, 0.80, 0.46)

W_WHITE = (1.0, 0.96, 0.86)
W_GREEN = (0.20, 1.0, 0.45)
W_RED = (1.0, 0.12, 0.08)
W_BLUE = (0.20, 0.35, 1.0)
W_SODIUM = (1.0, 0.66, 0.30)


def field_colour(x, y):
    """Ground albedo at a flat-zone point: airfield grass near the airfield, fields elsewhere."""
    airfield = (abs(x) <= 450 and -2550 <= y <= 1800) or in_rect(x, y, (-1050.0, -150.0, -1850.0, 750.0))
    if airfield:
        bx, by = int(math.floor(x / 300.0)), int(math.floor(y / 300.0))
        return jitter(GRASS_AF, 0.06, ihash(bx, by, 3))
    # farm fields: 600 x 450 m parcels, some split in two
    px, py = int(math.floor(x / 600.0)), int(math.floor(y / 450.0))
    split = ihash(px, py, 11)
    if split < 0.35:
        px = px * 2 + (1 if (x / 300.0) % 2 >= 1 else 0) + 1000
    elif split < 0.6:
        py = py * 3 + int((y / 150.0) % 3) + 1000
    k = int(ihash(px, py, 7) * len(FIELDS))
    return jitter(FIELDS[k], 0.08, ihash(px, py, 5))


def hill_colour(ix, iy, zc, nz):
    u = ihash(ix, iy, 21)
    if zc < 25:
        base = FIELDS[int(ihash(ix // 2, iy // 2, 9) * len(FIELDS))]
    elif zc < 300:
        t = ihash(ix // 2, iy // 3, 13)
        base = FOREST if t < 0.55 else ((0.22, 0.30, 0.14) if t < 0.85 else (0.34, 0.32, 0.19))
    else:
        base = (0.30, 0.28, 0.19) if ihash(ix // 2, iy // 2, 17) < 0.6 else (0.20, 0.26, 0.13)
    if nz < 0.94:    # steeper slopes: darker, browner
        base = (base[0] * 0.95 + 0.02, base[1] * 0.85, base[2] * 0.85)
    return jitter(base, 0.07, u)


# ---------------------------------------------------------------------------------------------
# terrain objects

def build_flat_terrain():
    """Flat zone: 150 m blocks, paved rectangles cut out, grouped in 1200 m tile objects."""
    tile = 1200.0
    x0, x1, y0, y1 = FLAT
    nbx, nby = int((x1 - x0) / BLOCK), int((y1 - y0) / BLOCK)
    per = int(tile / BLOCK)
    for ty in range(0, nby, per):
        for tx in range(0, nbx, per):
            cx = x0 + (tx + per / 2) * BLOCK
            cy = y0 + (ty + per / 2) * BLOCK
            o = Obj('terrain_flat_%+06d_%+06d' % (cx, cy), (cx, cy, 0.0))
            s = o.sub('fields', crease=0)
            for by in range(ty, min(ty + per, nby)):
                for bx in range(tx, min(tx + per, nbx)):
                    block_polys(s, x0 + bx * BLOCK, y0 + by * BLOCK, cx, cy)
            if not s.empty():
                OBJECTS.append(o)


def block_polys(s, bx0, by0, ox, oy):
    bx1, by1 = bx0 + BLOCK, by0 + BLOCK
    xs, ys = {bx0, bx1}, {by0, by1}
    hits = []
    for _, r in PAVED:
        if r[0] < bx1 and r[1] > bx0 and r[2] < by1 and r[3] > by0:
            hits.append(r)
            for v in (r[0], r[1]):
                if bx0 < v < bx1:
                    xs.add(v)
            for v in (r[2], r[3]):
                if by0 < v < by1:
                    ys.add(v)
    xs, ys = sorted(xs), sorted(ys)
    nx, ny = len(xs) - 1, len(ys) - 1
    ground = [[True] * nx for _ in range(ny)]
    for j in range(ny):
        for i in range(nx):
            mx, my = (xs[i] + xs[i + 1]) / 2, (ys[j] + ys[j + 1]) / 2
            if any(r[0] <= mx <= r[1] and r[2] <= my <= r[3] for r in hits):
                ground[j][i] = False
    used = [[False] * nx for _ in range(ny)]
    for j in range(ny):
        for i in range(nx):
            if not ground[j][i] or used[j][i]:
                continue
            i2 = i
            while i2 + 1 < nx and ground[j][i2 + 1] and not used[j][i2 + 1]:
                i2 += 1
            j2 = j
            while j2 + 1 < ny and all(ground[j2 + 1][k] and not used[j2 + 1][k] for k in range(i, i2 + 1)):
                j2 += 1
            for jj in range(j, j2 + 1):
                for ii in range(i, i2 + 1):
                    used[jj][ii] = True
            rx0, rx1, ry0, ry1 = xs[i], xs[i2 + 1], ys[j], ys[j2 + 1]
            col = field_colour((rx0 + rx1) / 2, (ry0 + ry1) / 2)
            quad_up(s, rx0 - ox, rx1 - ox, ry0 - oy, ry1 - oy, 0.0, colour=col)


def build_hills():
    """Triangulated heightfield outside the flat zone, in 2400 m tile objects."""
    nx = int((HILL_BOX[1] - HILL_BOX[0]) / HILL_CELL)
    ny = int((HILL_BOX[3] - HILL_BOX[2]) / HILL_CELL)
    per = 8
    count = 0
    for ty in range(0, ny, per):
        for tx in range(0, nx, per):
            cx = HILL_BOX[0] + (tx + per / 2) * HILL_CELL
            cy = HILL_BOX[2] + (ty + per / 2) * HILL_CELL
            o = Obj('terrain_hills_%+06d_%+06d' % (cx, cy), (cx, cy, 0.0))
            s = o.sub('heightfield', crease=70)
            for iy in range(ty, min(ty + per, ny)):
                for ix in range(tx, min(tx + per, nx)):
                    x0 = HILL_BOX[0] + ix * HILL_CELL
                    y0 = HILL_BOX[2] + iy * HILL_CELL
                    x1, y1 = x0 + HILL_CELL, y0 + HILL_CELL
                    mx, my = (x0 + x1) / 2, (y0 + y1) / 2
                    if in_rect(mx, my, FLAT):
                        continue
                    if math.hypot(mx - DOME_C[0], my - DOME_C[1]) > TERRAIN_R:
                        continue
                    za, zb = hill_grid_z(ix, iy), hill_grid_z(ix + 1, iy)
                    zc, zd = hill_grid_z(ix + 1, iy + 1), hill_grid_z(ix, iy + 1)
                    a = (x0 - cx, y0 - cy, za)
                    b = (x1 - cx, y0 - cy, zb)
                    c = (x1 - cx, y1 - cy, zc)
                    d = (x0 - cx, y1 - cy, zd)
                    if za == zb == zc == zd:
                        s.face([a, b, c, d], colour=hill_colour(ix, iy, za, 1.0))
                        count += 1
                        continue
                    tris = [(a, b, c), (a, c, d)] if cell_diagonal(ix, iy) else [(a, b, d), (b, c, d)]
                    for t in tris:
                        n = norm(newell(t))
                        zm = (t[0][2] + t[1][2] + t[2][2]) / 3
                        s.face(list(t), colour=hill_colour(ix, iy, zm, n[2]))
                        count += 1
            if not s.empty():
                OBJECTS.append(o)


# ---------------------------------------------------------------------------------------------
# runway, taxiways, apron, roads

SEG7 = {'0': 'abcdef', '2': 'abged', '4': 'fgbc', '6': 'afgedc'}


def digit_rects(ch, u0, v0, w=4.0, h=9.0, t=0.9):
    """Seven-segment digit as non-overlapping rectangles (u across, v along; top = +v)."""
    segs = SEG7[ch]
    r = []
    vm0, vm1 = v0 + h / 2 - t / 2, v0 + h / 2 + t / 2
    if 'a' in segs: r.append((u0, u0 + w, v0 + h - t, v0 + h))
    if 'g' in segs: r.append((u0, u0 + w, vm0, vm1))
    if 'd' in segs: r.append((u0, u0 + w, v0, v0 + t))
    top_lo = vm1 if 'g' in segs else vm0
    top_hi = v0 + h - t if 'a' in segs else v0 + h
    bot_lo = v0 + t if 'd' in segs else v0
    bot_hi = vm0
    if 'f' in segs: r.append((u0, u0 + t, top_lo, top_hi))
    if 'b' in segs: r.append((u0 + w - t, u0 + w, top_lo, top_hi))
    if 'e' in segs: r.append((u0, u0 + t, bot_lo, bot_hi))
    if 'c' in segs: r.append((u0 + w - t, u0 + w, bot_lo, bot_hi))
    if 'g' not in segs:   # join verticals across the middle gap
        if 'f' in segs and 'e' in segs:
            r.append((u0, u0 + t, vm0, vm1))
        if 'b' in segs and 'c' in segs:
            r.append((u0 + w - t, u0 + w, vm0, vm1))
    return r


def end_markings(designation):
    """Markings of one runway end in end coordinates (u right, v from the threshold)."""
    rects = []
    for k in range(6):                              # piano keys: 12 stripes 30 m x 1.8 m
        uc = 2.7 + 3.6 * k
        for sgn in (-1, 1):
            rects.append((sgn * uc - 0.9, sgn * uc + 0.9, 6.0, 36.0))
    w, gap = 4.0, 2.0                               # designation, 9 m high digits
    rects += digit_rects(designation[0], -gap / 2 - w, 48.0, w)
    rects += digit_rects(designation[1], gap / 2, 48.0, w)
    for v in (400.0,):                              # aiming point: 60 m x 9 m
        for sgn in (-1, 1):
            rects.append(tuple(sorted((sgn * 6.0, sgn * 15.0))) + (v, v + 60.0))
    for v, nbar in ((150, 3), (300, 3), (500, 2), (600, 2), (750, 1), (900, 1)):   # TDZ
        for k in range(nbar):
            for sgn in (-1, 1):
                a, b = 6.0 + 3.3 * k, 7.8 + 3.3 * k
                rects.append((min(sgn * a, sgn * b), max(sgn * a, sgn * b), float(v), v + 22.5))
    return rects


def build_runway():
    o = new_obj('runway_24_06', (0.0, 0.0, 0.0))
    m = o.sub('markings', colour=PAINT_W)
    zm = 0.05
    for des, sgn in (('24', 1), ('06', -1)):
        for u0, u1, v0, v1 in end_markings(des):
            # end frame -> R frame: runway 24 (sgn +1): x = u, y = THR + v; runway 06 rotated 180
            xa, xb = sgn * u0, sgn * u1
            ya, yb = sgn * (THR + v0), sgn * (THR + v1)
            quad_up(m, min(xa, xb), max(xa, xb), min(ya, yb), max(ya, yb), zm)
    y = THR + 70.0                                  # centreline: 30 m dashes, 20 m gaps
    while y + 30 <= -THR - 70.0:
        quad_up(m, -0.45, 0.45, y, y + 30, zm)
        y += 50.0
    for sgn in (-1, 1):                             # edge lines, 150 m pieces
        a, b = sorted((sgn * 21.7, sgn * 22.5))
        for k in range(int(RWY_LEN / 150)):
            quad_up(m, a, b, THR + 150 * k, THR + 150 * (k + 1), zm)
    s = o.sub('surface', colour=ASPHALT)
    for k in range(int(RWY_LEN / 100)):
        y0 = THR + 100 * k
        rubber = min(abs(y0 + 50 - (THR + 450)), abs(y0 + 50 - (-THR - 450)))
        col = jitter(ASPHALT, 0.04, ihash(k, 77))
        if rubber < 400:
            col = tuple(c * (0.78 + 0.22 * rubber / 400) for c in col)
        quad_up(s, -RWY_W / 2, RWY_W / 2, y0, y0 + 100, 0.0, colour=col)
    sh = o.sub('shoulders', colour=SHOULDER_C)
    for k in range(int(RWY_LEN / 150)):
        y0 = THR + 150 * k
        quad_up(sh, -RWY_W / 2 - SHOULDER, -RWY_W / 2, y0, y0 + 150, 0.0)
        quad_up(sh, RWY_W / 2, RWY_W / 2 + SHOULDER, y0, y0 + 150, 0.0)


def split_rect(sub, x0, x1, y0, y1, step, z=0.0, colour=None, jitter_key=None):
    nx = max(1, int(math.ceil((x1 - x0) / step - 1e-9)))
    ny = max(1, int(math.ceil((y1 - y0) / step - 1e-9)))
    for j in range(ny):
        for i in range(nx):
            a, b = x0 + (x1 - x0) * i / nx, x0 + (x1 - x0) * (i + 1) / nx
            c, d = y0 + (y1 - y0) * j / ny, y0 + (y1 - y0) * (j + 1) / ny
            col = colour
            if jitter_key is not None and colour is not None:
                col = jitter(colour, 0.05, ihash(jitter_key, i, j))
            quad_up(sub, a, b, c, d, z, colour=col)


def build_taxiways():
    o = new_obj('taxiways', (TWY_X, 0.0, 0.0))
    m = o.sub('taxiway_markings', colour=PAINT_Y)
    s = o.sub('taxiway_surface', colour=ASPHALT)
    ox = TWY_X
    for name, r in PAVED:
        if name != 'taxiway':
            continue
        split_rect(s, r[0] - ox, r[1] - ox, r[2], r[3], 100.0, colour=ASPHALT, jitter_key=int(r[2]))
    # centrelines (0.4 m) and holding positions
    for k in range(int((RWY_LEN + 40) / 152)):
        quad_up(m, -0.2, 0.2, THR - 20 + 152 * k, THR - 20 + 152 * (k + 1), 0.05)
    for yc in CONNECTORS:
        quad_up(m, TWY_W / 2, -RWY_W / 2 - SHOULDER - 30 - ox, yc - 0.2, yc + 0.2, 0.05)
        hx = -RWY_W / 2 - SHOULDER - 75 - ox       # runway holding position: 4 yellow lines
        for k in range(4):
            quad_up(m, hx + 0.9 * k, hx + 0.9 * k + 0.3, yc - TWY_W / 2 + 0.5, yc + TWY_W / 2 - 0.5, 0.05)


STANDS = [y + DY for y in (-560.0, -450.0, -340.0, -230.0, -120.0, 10.0, 130.0)]


def build_apron():
    x0, x1, y0, y1 = APRON
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    o = new_obj('apron', (cx, cy, 0.0))
    m = o.sub('apron_markings', colour=PAINT_Y)
    for ys in STANDS:                               # lead-in lines and stop bars
        xm = (-470 + x1 - 1) / 2
        quad_up(m, -470 - cx, xm - cx, ys - cy - 0.2, ys - cy + 0.2, 0.05)
        quad_up(m, xm - cx, x1 - 1 - cx, ys - cy - 0.2, ys - cy + 0.2, 0.05)
        quad_up(m, -472 - cx, -470 - cx, ys - cy - 3, ys - cy + 3, 0.05)
    for k in range(2):                              # apron edge line (white), two pieces
        xa = x0 + 2 + (x1 - x0 - 4) * k / 2
        xb = x0 + 2 + (x1 - x0 - 4) * (k + 1) / 2
        quad_up(m, xa - cx, xb - cx, y1 - 3 - cy, y1 - 2.6 - cy, 0.05, colour=PAINT_W)
    s = o.sub('apron_surface', colour=CONCRETE)
    split_rect(s, x0 - cx, x1 - cx, y0 - cy, y1 - cy, 100.0, colour=CONCRETE, jitter_key=99)


def build_roads():
    for name, r in PAVED:
        if name not in ('road', 'carpark'):
            continue
        long_x = (r[1] - r[0]) > (r[3] - r[2])
        step = 200.0
        if long_x:
            chunks = int(math.ceil((r[1] - r[0]) / 1200.0))
            for c in range(chunks):
                a = r[0] + (r[1] - r[0]) * c / chunks
                b = r[0] + (r[1] - r[0]) * (c + 1) / chunks
                cx, cy = (a + b) / 2, (r[2] + r[3]) / 2
                o = new_obj('road_%+06d_%+06d' % (cx, cy), (cx, cy, 0.0))
                s = o.sub('road_surface', colour=(0.20, 0.20, 0.21))
                split_rect(s, a - cx, b - cx, r[2] - cy, r[3] - cy, step)
        else:
            cx, cy = (r[0] + r[1]) / 2, (r[2] + r[3]) / 2
            o = new_obj('%s_%+06d_%+06d' % (name, cx, cy), (cx, cy, 0.0))
            s = o.sub(name + '_surface', colour=(0.20, 0.20, 0.21) if name == 'road' else (0.27, 0.27, 0.27))
            split_rect(s, r[0] - cx, r[1] - cx, r[2] - cy, r[3] - cy, step)


# ---------------------------------------------------------------------------------------------
# lights

def build_lights():
    o = new_obj('lights_runway_edge', (0.0, 0.0, 0.0))
    for k in range(int(RWY_LEN / 60) + 1):
        y = THR + 60 * k
        for x in (-RWY_W / 2 - 1.0, RWY_W / 2 + 1.0):
            o.light((x, y, 0.3), W_WHITE, 2.0, 1.0)

    o = new_obj('lights_threshold_24', (0.0, THR, 0.0))
    for k in range(15):
        o.light((-21.0 + 3.0 * k, -3.0, 0.3), W_GREEN, 2.0, 1.0)
    for sgn in (-1, 1):                              # wing bars
        for k in range(4):
            o.light((sgn * (28.0 + 3.0 * k), -3.0, 0.3), W_GREEN, 2.0, 1.0)

    o = new_obj('lights_runway_end_24', (0.0, -THR, 0.0))
    for k in range(13):
        o.light((-21.0 + 3.5 * k, 3.0, 0.3), W_RED, 2.0, 1.0)

    o = new_obj('lights_approach_24', (0.0, THR - 450.0, 0.0))
    for k in range(1, 31):                           # centreline barrettes every 30 m to 900 m
        y = THR - 30.0 * k - (THR - 450.0)
        for x in (-2.0, -1.0, 0.0, 1.0, 2.0):
            o.light((x, y, 0.3), W_WHITE, 2.5, 1.0)
    y = THR - 300.0 - (THR - 450.0)                  # 300 m crossbar
    for k in range(12):
        off = 3.5 + 1.5 * (k % 6)
        o.light((off if k < 6 else -off, y, 0.3), W_WHITE, 2.5, 1.0)
    for k in range(1, 10):                           # red side-row barrettes (inner 270 m)
        y = THR - 30.0 * k - (THR - 450.0)
        for sgn in (-1, 1):
            for x in (10.5, 12.0):
                o.light((sgn * x, y, 0.3), W_RED, 2.0, 1.0)

    o = new_obj('lights_papi_24', (-50.0, AIM, 0.0))
    for k, x in enumerate((-37.0, -46.0, -55.0, -64.0)):      # seen on the slope: 2 red, 2 white
        o.light((x + 50.0, 0.0, 0.3), W_RED if k < 2 else W_WHITE, 2.5, 1.0)

    # taxiway edge lights (blue): parallel taxiway and connectors
    lights = []
    inner, outer = TWY_X + TWY_W / 2 + 1.0, TWY_X - TWY_W / 2 - 1.0
    for k in range(int((RWY_LEN + 40) / 60) + 1):
        y = THR - 20 + 60 * k
        if not any(abs(y - yc) < TWY_W / 2 + 4 for yc in CONNECTORS):
            lights.append((inner, y))
        if not (APRON[2] - 4 <= y <= APRON[3] + 4):
            lights.append((outer, y))
    for yc in CONNECTORS:
        for x in (-155.0, -100.0, -45.0):
            lights.append((x, yc - TWY_W / 2 - 1.0))
            lights.append((x, yc + TWY_W / 2 + 1.0))
    for part, (ya, yb) in (('south', (-1e9, 0.0)), ('north', (0.0, 1e9))):
        o = new_obj('lights_taxiway_' + part, (TWY_X, (ya if ya > -1e8 else THR) / 2 + (yb if yb < 1e8 else -THR) / 2, 0.0))
        for x, y in lights:
            if ya <= y < yb:
                o.light((x - o.origin[0], y - o.origin[1], 0.3), W_BLUE, 2.0, 0.9)

    o = new_obj('lights_street_road_a', (0.0, ROAD_A_Y, 0.0))
    m = o.sub('lamp_posts', colour=(0.3, 0.3, 0.32))
    for k in range(-6, 7):
        x = 200.0 * k + 50.0
        y = -ROAD_W / 2 - 2.0
        m.solid(box_faces(x - 0.15, x + 0.15, y - 0.15, y + 0.15, 0.0, 8.0, bottom=False))
        o.light((x, y + 1.0, 8.2), W_SODIUM, 1.8, 0.85)


# ---------------------------------------------------------------------------------------------
# buildings

def windows_on_face(sub, axis, plane, sgn, a0, a1, z0, z1, nx, floors, rng, prob, size=(1.6, 1.3)):
    """Lit windows on a wall: axis 'x' = wall in plane x = const (facing sgn * x), else y."""
    for f in range(floors):
        zc = z0 + (f + 0.5) * (z1 - z0) / floors
        for i in range(nx):
            if rng.random() > prob:
                continue
            ac = a0 + (i + 0.5) * (a1 - a0) / nx
            w, h = size
            inten = round(rng.uniform(0.6, 0.95), 2)
            col = jitter(WARM_WINDOW, 0.08, rng.random())
            if axis == 'x':
                p = plane + sgn * 0.06
                pts = [(p, ac - w / 2, zc - h / 2), (p, ac + w / 2, zc - h / 2),
                       (p, ac + w / 2, zc + h / 2), (p, ac - w / 2, zc + h / 2)]
                sub.face(pts, col, inten, facing=(sgn, 0, 0))
            else:
                p = plane + sgn * 0.06
                pts = [(ac - w / 2, p, zc - h / 2), (ac + w / 2, p, zc - h / 2),
                       (ac + w / 2, p, zc + h / 2), (ac - w / 2, p, zc + h / 2)]
                sub.face(pts, col, inten, facing=(0, sgn, 0))


def pitched_house(sub, x0, x1, y0, y1, hw, hr, wall_c, roof_c, ridge_along_x=True):
    """Box walls + gabled roof as one convex solid (no floor)."""
    xm, ym = (x0 + x1) / 2, (y0 + y1) / 2
    if ridge_along_x:
        gab0 = [(x0, y0, 0), (x0, y0, hw), (x0, ym, hr), (x0, y1, hw), (x0, y1, 0)]
        gab1 = [(x1, y, z) for (_, y, z) in gab0]
    else:
        gab0 = [(x0, y0, 0), (x0 + 0, y0, hw), (xm, y0, hr), (x1, y0, hw), (x1, y0, 0)]
        gab1 = [(x, y1, z) for (x, _, z) in gab0]
    faces = loft_faces(gab0, gab1, caps=True)
    allp = gab0 + gab1
    c = centroid(allp)
    for f in faces:
        n = newell(f)
        out = sub_v(centroid(f), c)
        if n[2] != 0 and abs(n[2]) > 0.999 * math.sqrt(dot(n, n)):    # floor
            continue
        up = abs(n[2]) > 1e-9 and abs(n[2]) < 0.999 * math.sqrt(dot(n, n))
        sub.face(f, roof_c if up else wall_c, facing=out)


def sub_v(a, b):
    return sub(a, b)


def build_terminal(rng):
    x0, x1, y0, y1 = -590.0, -520.0, -500.0 + DY, -100.0 + DY
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    o = new_obj('terminal', (cx, cy, 0.0))
    hx, hy = (x1 - x0) / 2, (y1 - y0) / 2
    w = o.sub('windows')
    windows_on_face(w, 'x', hx, 1, -hy + 4, hy - 4, 1.5, 13.0, 60, 3, rng, 0.55, (3.0, 2.0))
    windows_on_face(w, 'y', -hy, -1, -hx + 4, hx - 4, 1.5, 13.0, 10, 3, rng, 0.6, (3.0, 2.0))
    windows_on_face(w, 'y', hy, 1, -hx + 4, hx - 4, 1.5, 13.0, 10, 3, rng, 0.6, (3.0, 2.0))
    g = o.sub('glass_front', colour=(0.25, 0.33, 0.38))
    g.face([(hx + 0.03, -hy + 2, 0.5), (hx + 0.03, hy - 2, 0.5), (hx + 0.03, hy - 2, 14.0),
            (hx + 0.03, -hy + 2, 14.0)], facing=(1, 0, 0))
    b = o.sub('building', colour=(0.55, 0.53, 0.50))
    b.solid(box_faces(-hx, hx, -hy, hy, 0.0, 15.0, bottom=False))
    r = o.sub('roof_plant', colour=(0.40, 0.40, 0.42))
    for k in range(4):
        yc = -hy + 60 + k * 90
        r.solid(box_faces(-15, 10, yc - 10, yc + 10, 15.0, 18.0, bottom=False))
    o.light((0.0, -hy + 1, 18.4), W_RED, 1.5, 0.9)
    o.light((0.0, hy - 1, 18.4), W_RED, 1.5, 0.9)
    # jet bridges
    jb = o.sub('jet_bridges', colour=(0.62, 0.62, 0.64))
    for ys in STANDS[1:5]:
        yl = ys - cy - 6
        jb.solid(box_faces(hx, hx + 38, yl - 1.5, yl + 1.5, 4.0, 7.0, bottom=True))
        jb.solid(box_faces(hx + 32, hx + 34, yl - 1.0, yl + 1.0, 0.0, 4.0, bottom=False))


def build_tower():
    o = new_obj('control_tower', (-640.0, 30.0 + DY, 0.0))
    cab = o.sub('cab_glass', colour=(0.55, 0.75, 0.65))
    cab_f = loft_faces(ngon_xy(0, 0, 6.0, 30.0), ngon_xy(0, 0, 6.6, 34.5), caps=False)
    c = (0, 0, 32)
    for f in cab_f:
        cab.face(f, intensity=0.55, facing=sub(centroid(f), c))
    roof = o.sub('cab_roof', colour=(0.35, 0.35, 0.37))
    roof.solid(loft_faces(ngon_xy(0, 0, 7.2, 34.5), ngon_xy(0, 0, 7.2, 35.6)))
    floor = o.sub('cab_floor', colour=(0.58, 0.56, 0.52))
    floor.solid(loft_faces(ngon_xy(0, 0, 5.0, 27.5), ngon_xy(0, 0, 7.0, 30.0)))
    sh = o.sub('shaft', colour=(0.62, 0.60, 0.56))
    sh.solid(box_faces(-3.0, 3.0, -3.0, 3.0, 0.0, 27.6, bottom=False))
    base = o.sub('base_building', colour=(0.52, 0.50, 0.47))
    base.solid(box_faces(-12.0, 12.0, -9.0, 9.0, 0.0, 7.0, bottom=False))
    ant = o.sub('antenna', colour=(0.5, 0.5, 0.5))
    ant.solid(box_faces(-0.2, 0.2, -0.2, 0.2, 35.6, 43.0, bottom=False))
    o.light((0.0, 0.0, 43.4), W_RED, 1.6, 1.0)


def hangar(name, x0, x1, y0, y1, wall_h, arch_h, wall_c, roof_c, door_lit, rng):
    """Barrel-roof hangar, door facing +x (apron). Convex: walls + 6 roof facets."""
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    o = new_obj(name, (cx, cy, 0.0))
    hx, hy = (x1 - x0) / 2, (y1 - y0) / 2
    n = 6
    arch = []
    for k in range(n + 1):
        a = math.pi * k / n
        arch.append((hy * math.cos(a), wall_h + arch_h * math.sin(a)))
    prof = [(hy, 0.0)] + arch + [(-hy, 0.0)]        # (y, z) end-wall profile; the arch runs +hy to -hy
    ring_a = [(-hx, y, z) for y, z in prof]
    ring_b = [(hx, y, z) for y, z in prof]
    d = o.sub('door', colour=(0.32, 0.34, 0.36))
    dw, dh = hy * 0.85, wall_h * 0.85
    dpts = [(hx + 0.06, -dw, 0.0), (hx + 0.06, dw, 0.0), (hx + 0.06, dw, dh), (hx + 0.06, -dw, dh)]
    if door_lit:
        d.face(dpts, colour=(1.0, 0.86, 0.62), intensity=0.75, facing=(1, 0, 0))
    else:
        d.face(dpts, facing=(1, 0, 0))
    w = o.sub('windows')
    windows_on_face(w, 'y', -hy, -1, -hx + 4, hx - 4, 3.0, 6.0, 12, 1, rng, 0.5, (2.0, 1.2))
    body = o.sub('hangar_body', colour=wall_c, crease=35)
    faces = loft_faces(ring_a, ring_b, caps=True)
    cc = (0.0, 0.0, (wall_h + arch_h) / 2)
    for f in faces:
        nrm = newell(f)
        out = sub(centroid(f), cc)
        if abs(nrm[2]) > 0.999 * math.sqrt(dot(nrm, nrm)) and centroid(f)[2] < 0.01:
            continue                                 # floor
        roofish = all(p[2] >= wall_h - 1e-6 for p in f)
        body.face(f, colour=roof_c if roofish else None, facing=out)
    o.light((hx - 1, 0.0, wall_h + arch_h + 0.5), W_RED, 1.5, 0.9)


def build_hangars(rng):
    hangar('hangar_1', -590.0, -510.0, 40.0 + DY, 100.0 + DY, 14.0, 9.0, (0.50, 0.52, 0.54), (0.42, 0.44, 0.46), True, rng)
    hangar('hangar_2', -590.0, -510.0, 112.0 + DY, 172.0 + DY, 14.0, 9.0, (0.54, 0.50, 0.44), (0.40, 0.40, 0.42), False, rng)
    hangar('hangar_3', -580.0, -520.0, 184.0 + DY, 234.0 + DY, 12.0, 7.0, (0.46, 0.49, 0.52), (0.38, 0.40, 0.44), True, rng)


def build_small_buildings(rng):
    # fire station between taxiway and runway side, north of the apron
    o = new_obj('fire_station', (-330.0, 520.0, 0.0))
    w = o.sub('door_lights')
    for k in range(3):
        y = -12 + 8 * k
        w.face([(15.06, y, 0.0), (15.06, y + 6, 0.0), (15.06, y + 6, 5.0), (15.06, y, 5.0)],
               colour=(1.0, 0.88, 0.7), intensity=0.7, facing=(1, 0, 0))
    b = o.sub('building')
    pitched_house(b, -15.0, 15.0, -15.0, 15.0, 7.0, 10.0, (0.62, 0.30, 0.24), (0.30, 0.30, 0.32), True)
    o.light((0.0, 0.0, 10.5), W_RED, 1.5, 0.8)
    # fuel farm: three tanks (octagonal prisms)
    o = new_obj('fuel_farm', (-420.0, -1300.0, 0.0))
    t = o.sub('tanks', colour=(0.72, 0.72, 0.70), crease=50)
    for k, (x, y) in enumerate(((-20.0, 0.0), (0.0, 0.0), (20.0, 0.0))):
        t.solid(loft_faces(ngon_xy(x, y, 7.5, 0.0), ngon_xy(x, y, 7.5, 11.0)), skip_down=True)
    tr = o.sub('tank_roofs', colour=(0.55, 0.55, 0.55))
    for x in (-20.0, 0.0, 20.0):
        top = (x, 0.0, 13.0)
        ring = ngon_xy(x, 0.0, 7.5, 11.0)
        for k in range(8):
            tr.face([ring[k], ring[(k + 1) % 8], top], facing=(ring[k][0] + ring[(k + 1) % 8][0] - 2 * x,
                                                             ring[k][1] + ring[(k + 1) % 8][1], 3.0))
    # maintenance sheds and offices along the landside road
    for k, (x, y, w_, d_) in enumerate(((-620.0, -620.0 + DY, 24.0, 40.0), (-615.0, -720.0 + DY, 20.0, 30.0),
                                       (-625.0, 300.0 + DY, 30.0, 50.0), (-420.0, -1400.0, 40.0, 22.0))):
        o = new_obj('shed_%d' % (k + 1), (x, y, 0.0))
        wn = o.sub('windows')
        windows_on_face(wn, 'x', w_ / 2, 1, -d_ / 2 + 2, d_ / 2 - 2, 1.0, 6.0, int(d_ / 4), 2, rng, 0.4)
        b = o.sub('building')
        col = jitter((0.58, 0.55, 0.50), 0.1, rng.random())
        pitched_house(b, -w_ / 2, w_ / 2, -d_ / 2, d_ / 2, 6.0, 9.0, col, (0.36, 0.26, 0.22), False)
    # apron floodlight masts
    o = new_obj('apron_flood_masts', (-505.0, -200.0 + DY, 0.0))
    m = o.sub('masts', colour=(0.45, 0.45, 0.47))
    for k in range(5):
        y = -400.0 + 200.0 * k
        m.solid(box_faces(-0.4, 0.4, y - 0.4, y + 0.4, 0.0, 25.0, bottom=False))
        m.solid(box_faces(-0.6, 2.2, y - 2.0, y + 2.0, 25.0, 25.8, bottom=False))
        o.light((1.2, y, 25.5), W_SODIUM, 2.5, 1.0)
    # car park lamps
    o = new_obj('carpark_lamps', ((CARPARK[0] + CARPARK[1]) / 2, (CARPARK[2] + CARPARK[3]) / 2, 0.0))
    m = o.sub('posts', colour=(0.35, 0.35, 0.37))
    for k in range(4):
        y = -90.0 + 60.0 * k
        m.solid(box_faces(-0.15, 0.15, y - 0.15, y + 0.15, 0.0, 9.0, bottom=False))
        o.light((0.0, y, 9.2), W_SODIUM, 1.8, 0.9)
    # parked cars (small boxes) in the car park
    cars = new_obj('carpark_cars', ((CARPARK[0] + CARPARK[1]) / 2, (CARPARK[2] + CARPARK[3]) / 2, 0.0))
    cs = cars.sub('cars')
    for row in (-30.0, -10.0, 10.0, 30.0):
        for k in range(20):
            if rng.random() < 0.35:
                continue
            y = -100.0 + 10.5 * k
            col = [(0.6, 0.6, 0.62), (0.2, 0.2, 0.22), (0.5, 0.12, 0.1), (0.15, 0.2, 0.4), (0.7, 0.7, 0.68)][int(rng.random() * 5)]
            for f in box_faces(row - 2.2, row + 2.2, y - 0.9, y + 0.9, 0.0, 1.5, bottom=False):
                cs.face(f, col, facing=sub(centroid(f), (row, y, 0.75)))


def build_village(rng):
    x0, x1, y0, y1 = VILLAGE
    houses = []
    tries = 0
    while len(houses) < 34 and tries < 2000:
        tries += 1
        x, y = rng.uniform(x0, x1), rng.uniform(y0, y1)
        if abs(x - 1100.0) < 14 or on_paved(x, y, 12.0):
            continue
        if any(abs(x - hx) < 26 and abs(y - hy) < 26 for hx, hy in houses):
            continue
        houses.append((x, y))
    houses.sort(key=lambda p: (round(p[1], 3), round(p[0], 3)))
    groups = {}
    for x, y in houses:
        key = (int((x - x0) // 400), int((y - y0) // 260))
        groups.setdefault(key, []).append((x, y))
    for key in sorted(groups):
        pts = groups[key]
        gx = sum(p[0] for p in pts) / len(pts)
        gy = sum(p[1] for p in pts) / len(pts)
        o = new_obj('village_%d_%d' % key, (gx, gy, 0.0))
        wn = o.sub('lit_windows')
        b = o.sub('houses')
        for x, y in pts:
            lx, ly = x - gx, y - gy
            w_, d_ = rng.uniform(8, 12), rng.uniform(10, 15)
            along = rng.random() < 0.5
            wall = jitter((0.66, 0.60, 0.52), 0.12, rng.random())
            roof = [(0.45, 0.20, 0.15), (0.30, 0.28, 0.28), (0.40, 0.26, 0.20)][int(rng.random() * 3)]
            pitched_house(b, lx - w_ / 2, lx + w_ / 2, ly - d_ / 2, ly + d_ / 2, 5.5, 8.5, wall, roof, along)
            for sgn in (-1, 1):
                if rng.random() < 0.6:
                    wx = lx + sgn * (w_ / 2 + 0.06)
                    wy = ly + rng.uniform(-d_ / 4, d_ / 4)
                    pts_ = [(wx, wy - 0.7, 1.6), (wx, wy + 0.7, 1.6), (wx, wy + 0.7, 2.8), (wx, wy - 0.7, 2.8)]
                    wn.face(pts_, jitter(WARM_WINDOW, 0.1, rng.random()), round(rng.uniform(0.6, 0.9), 2),
                            facing=(sgn, 0, 0))
        if wn.empty():
            o.subs.remove(wn)
    o = new_obj('lights_village_street', (1100.0, (y0 + y1) / 2, 0.0))
    m = o.sub('lamp_posts', colour=(0.3, 0.3, 0.32))
    for k in range(4):
        y = (y0 - 200.0) + 180.0 * k - (y0 + y1) / 2
        m.solid(box_faces(5.0, 5.3, y - 0.15, y + 0.15, 0.0, 7.0, bottom=False))
        o.light((5.1, y, 7.2), W_SODIUM, 1.8, 0.85)


def build_forests(rng):
    patches = [(-1500.0, -4300.0, 260.0, 60), (1900.0, -1500.0, 230.0, 50), (-1900.0, 1400.0, 260.0, 55),
               (1300.0, 2600.0, 220.0, 45), (2300.0, -5000.0, 250.0, 50), (-2300.0, -2300.0, 240.0, 50),
               (900.0, -6000.0, 200.0, 40), (-1200.0, -6300.0, 220.0, 40), (2500.0, 1000.0, 200.0, 40),
               (-2600.0, -800.0, 180.0, 35), (2000.0, -3300.0, 160.0, 30), (-800.0, 2900.0, 200.0, 40),
               (4200.0, 4200.0, 300.0, 45), (-4300.0, 3600.0, 300.0, 45), (-3900.0, -1800.0, 300.0, 40),
               (4100.0, -1200.0, 300.0, 40)]
    for n, (px, py, rad, count) in enumerate(patches):
        o = new_obj('forest_%02d' % (n + 1), (px, py, 0.0))
        s = o.sub('trees', crease=75)
        placed = []
        tries = 0
        while len(placed) < count and tries < count * 30:
            tries += 1
            a, r = rng.uniform(0, 2 * math.pi), rad * math.sqrt(rng.random())
            x, y = px + r * math.cos(a) * 1.3, py + r * math.sin(a)
            if on_paved(x, y, 15.0) or (abs(x) < 500 and y < 1800) or in_rect(x, y, VILLAGE, 20):
                continue
            if any((x - qx) ** 2 + (y - qy) ** 2 < 64 for qx, qy in placed):
                continue
            placed.append((x, y))
        for x, y in placed:
            z0 = terrain_z(x, y) - 0.5
            h = rng.uniform(11, 20)
            rb = h * rng.uniform(0.25, 0.35)
            col = jitter(FOREST, 0.18, rng.random())
            base = ngon_xy(x - px, y - py, rb, z0 + 2.0, n=6, phase=rng.uniform(0, 1))
            apex = (x - px, y - py, z0 + h)
            for k in range(6):
                p, q = base[k], base[(k + 1) % 6]
                s.face([p, q, apex], col, facing=(p[0] + q[0] - 2 * (x - px), p[1] + q[1] - 2 * (y - py), 0.5 * rb))
            trunk = [(x - px + 0.4 * math.cos(t), y - py + 0.4 * math.sin(t), z0) for t in (0.3, 2.4, 4.5)]
            for k in range(3):
                p, q = trunk[k], trunk[(k + 1) % 3]
                s.face([p, q, (q[0], q[1], z0 + 2.2), (p[0], p[1], z0 + 2.2)], (0.18, 0.13, 0.09),
                       facing=(p[0] + q[0] - 2 * (x - px), p[1] + q[1] - 2 * (y - py), 0.0))
        if s.empty():
            OBJECTS.remove(o)


# ---------------------------------------------------------------------------------------------
# aircraft: every subobject a closed convex solid with outward faces

AIRCRAFT_TYPES = {
    # length, fuselage radius, span, root chord, tip chord, sweep (m), tail colour, engines
    'twinjet_a': dict(L=37.6, R=2.0, span=34.1, cr=7.0, ct=1.6, sweep=8.5, engines=2,
                      tail=(0.10, 0.22, 0.55), belly=(0.85, 0.86, 0.88)),
    'twinjet_b': dict(L=39.5, R=1.9, span=35.8, cr=7.3, ct=1.5, sweep=9.0, engines=2,
                      tail=(0.65, 0.10, 0.10), belly=(0.80, 0.80, 0.82)),
    'turboprop': dict(L=27.2, R=1.4, span=27.0, cr=2.6, ct=1.5, sweep=0.6, engines=2, prop=True,
                      tail=(0.12, 0.45, 0.30), belly=(0.86, 0.86, 0.86)),
    'bizjet': dict(L=18.0, R=1.0, span=16.5, cr=3.2, ct=1.1, sweep=3.0, engines=0, rear=True,
                   tail=(0.75, 0.62, 0.25), belly=(0.88, 0.88, 0.90)),
}


def build_aircraft(name, kind, x, y, turn):
    t = AIRCRAFT_TYPES[kind]
    L, R, span, cr, ct, sweep = t['L'], t['R'], t['span'], t['cr'], t['ct'], t['sweep']
    o = new_obj(name, (x, y, 0.0), turn=turn)
    zc = R + 1.3 * (R / 2.0) + 0.6                 # fuselage axis height (gear)
    yn = 0.5 * L - 0.13 * L                          # nose section start
    yt = -0.5 * L + 0.22 * L                         # tail cone start
    white = t['belly']
    # decals first: window strips (thin convex boxes on the flat side faces)
    side = R * math.cos(math.pi / 8)
    for sgn in (-1, 1):
        wins = o.sub('cabin_windows_' + ('left' if sgn < 0 else 'right'), colour=WARM_WINDOW)
        a, b = sorted((sgn * side, sgn * (side + 0.04)))
        for f in box_faces(a, b, yt + 1.0, yn - 1.0, zc + 0.05 * R, zc + 0.28 * R):
            wins.face(f, intensity=0.55, facing=sub(centroid(f), (sgn * side, (yt + yn) / 2, zc + 0.16 * R)))
    ck = o.sub('cockpit_windows', colour=(0.08, 0.10, 0.14))
    ck.solid(box_faces(-0.55 * R, 0.55 * R, yn + 0.55, yn + 1.35, zc + 0.38 * R, zc + 0.45 * R + 0.1))
    fus = o.sub('fuselage', colour=white, crease=50)
    fus.solid(loft_faces(ngon_xz(0, zc, R, yt), ngon_xz(0, zc, R, yn)))
    nose = o.sub('nose', colour=white, crease=50)
    nose.solid(loft_faces(ngon_xz(0, zc, R, yn), ngon_xz(0, zc - 0.35 * R, 0.22 * R, 0.5 * L)))
    tc = o.sub('tail_cone', colour=white, crease=50)
    tc.solid(loft_faces(ngon_xz(0, zc + 0.55 * R, 0.25 * R, -0.5 * L), ngon_xz(0, zc, R, yt)))
    # wings (low wing, or high wing for the turboprop)
    high = t.get('prop', False)
    wz0 = zc + 0.72 * R if high else zc - 0.75 * R
    wz1 = wz0 + (0.35 if high else 0.45)
    wy = -0.03 * L if not t.get('rear') else -0.06 * L
    half = span / 2
    for sgn, side_name in ((-1, 'left'), (1, 'right')):
        root_x = sgn * 0.5 * R
        tip_x = sgn * half
        plan = [(root_x, wy + cr / 2), (root_x, wy - cr / 2),
                (tip_x, wy - sweep - ct / 2 - 0.3 * (cr - ct)), (tip_x, wy - sweep + ct / 2 - 0.3 * (cr - ct))]
        wsub = o.sub('wing_' + side_name, colour=(0.72, 0.73, 0.75))
        wsub.solid(slab_xy(plan, wz0, wz1))
        # horizontal stabiliser
        hs = 0.36 * span / 2 if not t.get('prop') else 0.3 * span / 2
        hy = -0.5 * L + 2.0 + (0.0 if not t.get('rear') else 0.0)
        hz0 = zc + 0.35 * R
        hcr, hct, hsw = 0.14 * L, 0.06 * L, 0.09 * L
        if t.get('prop') or t.get('rear'):
            hz0 = zc + 0.55 * R + 0.62 * 0.16 * L   # T-tail on top of the fin
            hy = -0.5 * L + 0.5
        plan_h = [(sgn * 0.3 * R, hy + hcr), (sgn * 0.3 * R, hy), (sgn * hs, hy + hsw * 0.5),
                  (sgn * hs, hy + hsw * 0.5 + hct)]
        hsub = o.sub('stabiliser_' + side_name, colour=(0.72, 0.73, 0.75))
        hsub.solid(slab_xy(plan_h, hz0, hz0 + 0.3))
        # engines
        if t['engines'] and not t.get('prop'):
            ex = sgn * 0.34 * half
            ey1 = wy + cr / 2 + 2.6 - 0.34 * sweep
            ey0 = ey1 - 4.6
            er = 0.55 * R
            es = o.sub('engine_' + side_name, colour=(0.60, 0.61, 0.63), crease=50)
            es.solid(loft_faces(ngon_xz(ex, wz0 - er - 0.3, er, ey0), ngon_xz(ex, wz0 - er - 0.3, er, ey1)))
            py_ = o.sub('pylon_' + side_name, colour=(0.62, 0.62, 0.64))
            py_.solid(box_faces(ex - 0.2, ex + 0.2, ey0 + 0.6, ey1 - 0.6, wz0 - 0.35, wz0))
        if t.get('prop'):
            ex = sgn * 0.3 * half
            es = o.sub('nacelle_' + side_name, colour=(0.80, 0.80, 0.82), crease=50)
            es.solid(loft_faces(ngon_xz(ex, wz0 - 0.3, 0.55, wy - cr / 2 - 1.0),
                                ngon_xz(ex, wz0 - 0.3, 0.55, wy + cr / 2 + 2.2)))
            pr = o.sub('propeller_' + side_name, colour=(0.12, 0.12, 0.13))
            pr.solid(box_faces(ex - 0.12, ex + 0.12, wy + cr / 2 + 2.25, wy + cr / 2 + 2.45, wz0 - 2.0, wz0 + 1.4))
        if t.get('rear'):
            ex = sgn * (R + 0.55)
            es = o.sub('engine_' + side_name, colour=(0.62, 0.62, 0.64), crease=50)
            es.solid(loft_faces(ngon_xz(ex, zc + 0.35 * R, 0.5, -0.5 * L + 0.2 * L),
                                ngon_xz(ex, zc + 0.35 * R, 0.5, -0.5 * L + 0.2 * L + 3.2)))
        o.light((tip_x + sgn * 0.2, wy - sweep - 0.3 * (cr - ct), wz1 + 0.1),
                W_GREEN if sgn > 0 else W_RED, 1.5, 0.9)
    # fin (profile in y, z; extruded in x)
    fh = 0.16 * L + R
    fcr, fct, fsw = 0.17 * L, 0.08 * L, 0.10 * L
    fy0 = -0.5 * L + 0.3
    fz0 = zc + 0.55 * R
    prof = [(fy0 + fcr, fz0), (fy0, fz0), (fy0 - 0.0 + fsw * 0.4, fz0 + fh), (fy0 + fsw * 0.4 + fct, fz0 + fh)]
    fin = o.sub('fin', colour=t['tail'])
    fin.solid(slab_yz(prof, -0.22, 0.22))
    # landing gear
    g = o.sub('gear_nose', colour=(0.25, 0.25, 0.26))
    g.solid(box_faces(-0.25, 0.25, 0.38 * L - 0.3, 0.38 * L + 0.3, 0.0, zc - 0.8 * R))
    for sgn, side_name in ((-1, 'left'), (1, 'right')):
        g = o.sub('gear_main_' + side_name, colour=(0.25, 0.25, 0.26))
        gx = sgn * (R + 0.4)
        g.solid(box_faces(gx - 0.35, gx + 0.35, wy - 1.0, wy + 0.2, 0.0, wz0 if not high else zc - 0.7 * R))


def build_apron_aircraft():
    # parked nose-in towards the terminal (R-frame -x): turn -90
    spec = [('aircraft_twinjet_1', 'twinjet_a', STANDS[0]), ('aircraft_twinjet_2', 'twinjet_b', STANDS[1]),
            ('aircraft_turboprop_1', 'turboprop', STANDS[2]), ('aircraft_twinjet_3', 'twinjet_a', STANDS[3]),
            ('aircraft_bizjet_1', 'bizjet', STANDS[4]), ('aircraft_turboprop_2', 'turboprop', STANDS[6])]
    for name, kind, ys in spec:
        L = AIRCRAFT_TYPES[kind]['L']
        build_aircraft(name, kind, -470.0 + 2.0 + L / 2, ys, -90.0)


# ---------------------------------------------------------------------------------------------
# sky dome and sun

def sky_target(el, rel_az):
    """Final (fogged) sky colour wanted at elevation el, azimuth rel_az (deg from the sun)."""
    rows = [(-5, (0.58, 0.42, 0.34)), (0, (0.74, 0.49, 0.32)), (2, (0.70, 0.48, 0.34)),
            (5, (0.57, 0.43, 0.36)), (9, (0.40, 0.33, 0.36)), (14, (0.26, 0.22, 0.33)),
            (20, (0.16, 0.15, 0.29)), (28, (0.11, 0.10, 0.24)), (45, (0.08, 0.08, 0.20))]
    for (e0, c0), (e1, c1) in zip(rows, rows[1:]):
        if el <= e1:
            t = min(1.0, max(0.0, (el - e0) / (e1 - e0)))
            base = tuple(a + (b - a) * t for a, b in zip(c0, c1))
            break
    else:
        base = rows[-1][1]
    # brightness only (each band has one hue): glow around the sun, a broad warm west, darker east
    d = math.degrees(math.acos(max(-1.0, min(1.0, math.cos(math.radians(el)) * math.cos(math.radians(SUN_EL)) *
                                               math.cos(math.radians(rel_az)) + math.sin(math.radians(el)) *
                                               math.sin(math.radians(SUN_EL))))))
    low = max(0.0, 1.0 - max(el, 0.0) / 25.0)
    m = 0.78 + 0.36 * math.exp(-d / 9.0) + 0.16 * math.exp(-d / 30.0) \
        + 0.08 * max(0.0, math.cos(math.radians(rel_az))) * low \
        - 0.20 * max(0.0, -math.cos(math.radians(rel_az))) * low
    return tuple(min(1.0, max(0.0, v * m)) for v in base)


DOME_ELEVATIONS = [-5.0, -1.5, 0.0, 1.0, 2.0, 3.0, 4.0, 5.5, 7.0, 8.5, 10.0, 12.0, 14.0, 16.5, 19.0,
                   22.0, 26.0, 30.0, 37.0, 45.0]


def dome_radius(el):
    # horizon rows at 16 km; higher rows nearer (less fogged) so that the zenith side stays dark
    if el <= 6.0:
        return 16000.0
    return 16000.0 - 10000.0 * min(1.0, (el - 6.0) / 39.0) ** 0.8


DOME_ROWS = [(e, dome_radius(e)) for e in DOME_ELEVATIONS]


def build_sky():
    segs = 72
    cx, cy = DOME_C
    wcx, wcy, _ = r2w(cx, cy)
    mid = r2w(0.0, -3000.0)
    fc = FOG['colour']
    pts = {}
    for i in range(segs + 1):
        az = 360.0 * i / segs                        # true azimuth (world)
        for j, (el, r) in enumerate(DOME_ROWS):
            z = r * math.tan(math.radians(el))
            x = wcx + r * math.sin(math.radians(az))
            y = wcy + r * math.cos(math.radians(az))
            dist = math.hypot(x - mid[0], y - mid[1]) * 0.96
            f = min(1.0, max(0.0, (dist - FOG['start']) / (FOG['end'] - FOG['start'])))
            tgt = sky_target(el, az - SUN_AZ)
            raw = tuple(min(1.0, max(0.0, (tgt[k] - f * fc[k]) / max(1e-6, 1 - f))) for k in range(3))
            pts[(i, j)] = ((x, y, z), raw)
    band_colour = []        # one hue per band: the normalised mean over the ring
    for j in range(len(DOME_ROWS) - 1):
        acc = [0.0, 0.0, 0.0]
        for i in range(segs):
            for jj in (j, j + 1):
                for k in range(3):
                    acc[k] += pts[(i, jj)][1][k]
        mx = max(acc) or 1.0
        band_colour.append(tuple(round(v / mx, 4) for v in acc))
    for i in range(segs):
        az0 = 360.0 * i / segs
        azm = math.radians(az0 + 180.0 / segs)
        # sort after everything else: sphere centre pushed out beyond the dome
        o = Obj('sky_%03d' % int(round(az0 * 10)), (0.0, 0.0, 0.0), frame='W')
        s = o.sub('sky_band', protected=True, crease=0)
        for j in range(len(DOME_ROWS) - 1):
            corners = [pts[(i + 1, j)], pts[(i, j)], pts[(i, j + 1)], pts[(i + 1, j + 1)]]
            # counter-clockwise seen from inside (the dome centre): i+1 is clockwise in azimuth
            col = band_colour[j]
            lum_c = sum(col)
            inten = [round(min(1.0, max(0.0, sum(c[1]) / lum_c)), 3) for c in corners]
            p = [c[0] for c in corners]
            inward = (wcx - centroid(p)[0], wcy - centroid(p)[1], 0.0)
            s.face(p, col, inten, facing=inward)
        # explicit bounding sphere centred beyond the dome so that the sky sorts last
        far = (wcx + 21000.0 * math.sin(azm), wcy + 21000.0 * math.cos(azm), 0.0)
        rad = max(math.sqrt(dot(sub(v, far), sub(v, far))) for v in s.verts) + 1.0
        o.sphere = (far, math.ceil(rad))
        OBJECTS.append(o)
    # the sun: a self-lit disc facing the approach path, 11 km away, in front of the dome
    sd = sun_vector()
    centre = add((mid[0], mid[1], 120.0), mul(sd, 11000.0))
    o = new_obj('sun', (0.0, 0.0, 0.0), frame='W')
    s = o.sub('sun_disc', colour=(1.0, 0.86, 0.62), protected=True)
    e1 = norm(cross(sd, (0.0, 0.0, 1.0)))
    e2 = cross(e1, sd)
    rad = 11000.0 * math.tan(math.radians(0.75))
    ring = [add(centre, add(mul(e1, rad * math.cos(2 * math.pi * k / 10)), mul(e2, rad * math.sin(2 * math.pi * k / 10))))
            for k in range(10)]
    s.face(ring, intensity=1.0, facing=mul(sd, -1.0))


def sun_vector():
    a, e = math.radians(SUN_AZ), math.radians(SUN_EL)
    return (math.sin(a) * math.cos(e), math.cos(a) * math.cos(e), math.sin(e))


# ---------------------------------------------------------------------------------------------
# observer path

def observer(frames):
    last = frames - 1
    y0, y1 = THR - 3200.0, THR - 20.0
    tg = math.tan(math.radians(GLIDE))
    # (fraction of the path, lateral offset m, heading offset, pitch, roll)
    keys = [(0.0, -38.0, 1.1, -3.0, 2.0), (0.2, -24.0, 0.9, -3.1, 1.0), (0.4, -10.0, 0.5, -3.0, -1.5),
            (0.6, 0.5, -0.2, -2.9, -0.8), (0.8, 1.5, -0.1, -2.8, 0.7), (1.0, 0.0, 0.0, -2.2, 0.0)]
    out = []
    for frac, dx, dh, pitch, roll in keys:
        f = min(last, int(round(frac * frames)))
        y = y0 + (y1 - y0) * f / last
        h = (AIM - y) * tg
        x, yy, z = r2w(dx, y, h)
        out.append((f, (x, yy, z), (RWY_HDG + dh) % 360.0, pitch, roll))
    return out


# ---------------------------------------------------------------------------------------------
# output

def num(v):
    v = round(float(v), 4)
    if v == 0:
        return '0'
    if v == int(v) and abs(v) < 1e12:
        return str(int(v))
    s = ('%.4f' % v).rstrip('0').rstrip('.')
    return s


def vec(v):
    return '[' + ', '.join(num(c) for c in v) + ']'


def jstr(s):
    out = '"'
    for ch in s:
        if ch in '"\\':
            out += '\\' + ch
        elif ord(ch) < 32:
            out += '\\u%04x' % ord(ch)
        else:
            out += ch
    return out + '"'


def object_layer(name):
    """Priority class for the scene manager: the sky behind everything, the sun disc in front of
    the sky, surfaces that things stand on below the things on them."""
    if name.startswith('sky_'):
        return -3
    if name == 'sun':
        return -2
    if name.startswith(('terrain_', 'runway_', 'taxiways', 'apron', 'road_', 'carpark_')) and name != 'carpark_cars' \
            and name != 'carpark_lamps':
        return -1
    return 0


def parts_by_distance(name):
    """Objects made of separate, free-standing parts (a row of tanks, houses, cars, trees) rank
    their subobjects by distance; objects whose parts touch (walls and roofs, wings on a
    fuselage, markings on a runway) keep the modeller's database order."""
    return name.startswith(('fuel_farm', 'village_', 'carpark_cars', 'forest_'))


def obj_world_pose(o):
    if o.frame == 'W':
        return o.origin, 0.0
    return r2w(*o.origin), (RWY_HDG + o.turn) % 360.0


def write(frames, out):
    w = out.write
    w('{\n"format": "cig-scene",\n"version": 1,\n"name": "airfield approach at dusk (runway 24)",\n')
    w('"raster": 512,\n"view": { "near": 1.0, "light_point_min_diameter": 6 },\n')
    w('"channels": [\n')
    chans = [('left', -40), ('centre', 0), ('right', 40)]
    w(',\n'.join('  { "name": %s, "yaw": %d, "pitch": 0, "fov": 40 }' % (jstr(n), y) for n, y in chans))
    w('\n],\n')
    sv = sun_vector()
    w('"lighting": { "sun_direction": %s, "sun_intensity": 0.5, "ambient": 0.35 },\n' % vec(sv))
    w('"fog": { "colour": %s, "start": %s, "end": %s },\n' % (vec(FOG['colour']), num(FOG['start']), num(FOG['end'])))
    w('"background": %s,\n' % vec(BACKGROUND))
    w('"observer": { "keyframes": [\n')
    kf = observer(frames)
    w(',\n'.join('  { "frame": %d, "position": %s, "heading": %s, "pitch": %s, "roll": %s }'
                 % (f, vec(p), num(h), num(pi), num(r)) for f, p, h, pi, r in kf))
    w('\n] },\n"objects": [\n')
    first = True
    for o in OBJECTS:
        if not first:
            w(',\n')
        first = False
        pos, hdg = obj_world_pose(o)
        w('{ "name": %s, "position": %s' % (jstr(o.name), vec(pos)))
        layer = object_layer(o.name)
        if layer:
            w(', "layer": %d' % layer)
        if parts_by_distance(o.name) and len([s for s in o.subs if not s.empty()]) > 1:
            w(', "subobject_order": "distance"')
        if hdg:
            w(', "heading": %s' % num(hdg))
        if o.sphere:
            w(', "bounding_sphere": { "centre": %s, "radius": %s }' % (vec(o.sphere[0]), num(o.sphere[1])))
        w(',\n "subobjects": [')
        subs = [s for s in o.subs if not s.empty()]
        for si, s in enumerate(subs):
            w('\n  { "name": %s' % jstr(s.name))
            if s.crease is not None:
                w(', "crease_angle": %s' % num(s.crease))
            if s.colour is not None:
                w(', "colour": %s' % vec(s.colour))
            if s.protected:
                w(', "protected": true')
            w(',\n   "vertices": [')
            for k in range(0, len(s.verts), 8):
                w('\n    ' + ', '.join(vec(v) for v in s.verts[k:k + 8]) + (',' if k + 8 < len(s.verts) else ''))
            w('],\n   "polygons": [')
            for pi, (idx, col, inten) in enumerate(s.polys):
                t = '\n    { "indices": [' + ', '.join(str(i) for i in idx) + ']'
                if col is not None:
                    t += ', "colour": ' + vec(col)
                if inten is not None:
                    t += ', "intensity": ' + (vec(inten) if isinstance(inten, list) else num(inten))
                t += ' }' + (',' if pi + 1 < len(s.polys) else '')
                w(t)
            w('] }' + (',' if si + 1 < len(subs) else ''))
        w('],\n "light_points": [')
        for li, (p, c, d, it) in enumerate(o.lights):
            w('\n  { "position": %s, "diameter": %s, "colour": %s, "intensity": %s }%s'
              % (vec(p), num(d), vec(c), num(it), ',' if li + 1 < len(o.lights) else ''))
        w('] }')
    w('\n]\n}\n')


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--frames', type=int, default=150, help='observer path length in frames (default 150)')
    args = ap.parse_args()
    if args.frames < 2:
        ap.error('--frames must be at least 2')
    rng = random.Random(SEED)
    global BUMPS
    BUMPS = make_bumps(random.Random(SEED + 1))
    # near objects first in the file (the scene manager sorts anyway)
    build_runway()
    build_taxiways()
    build_apron()
    build_roads()
    build_lights()
    build_terminal(rng)
    build_tower()
    build_hangars(rng)
    build_small_buildings(rng)
    build_apron_aircraft()
    build_village(rng)
    build_forests(random.Random(SEED + 2))
    build_flat_terrain()
    build_hills()
    build_sky()
    OBJECTS[:] = [o for o in OBJECTS if o.lights or any(not s.empty() for s in o.subs)]
    write(args.frames, sys.stdout)
    npoly = sum(len(s.polys) for o in OBJECTS for s in o.subs)
    nlight = sum(len(o.lights) for o in OBJECTS)
    sys.stderr.write('make_airfield: %d objects, %d polygons, %d light points, %d frames\n'
                     % (len(OBJECTS), npoly, nlight, args.frames))


BUMPS = []
HCACHE = {}

if __name__ == '__main__':
    main()
