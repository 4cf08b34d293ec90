#!/usr/bin/env python3
"""Generate a large cig-scene world, to show what the scene manager's culling saves.

    python3 tools/make_world.py --out scenes/world.json --scale 0.1            # the committed world
    python3 tools/make_world.py --out /tmp/world.json --print-stats            # >= 200 k triangles
    python3 tools/make_world.py --out /tmp/world10.json --scale 10 --print-stats   # >= 2 M triangles

Standard library only and deterministic: the same --scale and --seed (default 1) give the same
bytes. The file is written to a temporary file beside --out and renamed, so an error leaves no
partial output. Bad options (a scale outside (0, 100], an unwritable path) exit with status 2.

The world is a square of 40 km x 40 km at scale 1, its side growing with sqrt(scale) and its
content with the scale (the density stays the same):

  * terrain tiles: a grid of 1 km ground tiles (layer -2), each its own object: 4 x 4 cells of
    250 m, a flat quad where the cell is level, two triangles on the hills; its subobjects are the
    decals that lie on it listed before the ground, as the airfield scene lists runway markings
    before the runway: `roads` (roads between towns, town streets), `water` (river, harbour basin),
    then `ground`. Decals on a hill cell are cut along its triangles and follow their planes;
  * towns: a street grid and houses (boxes with gabled roofs, flat-roofed blocks in the centre),
    one object per house; farms (a house and a barn) over the open country;
  * forests: stands of 4 to 7 trees (a four-sided cone or double pyramid each, one subobject per
    tree, ordered by distance), mostly on the hills;
  * airfields: a runway object (layer -1: markings before runway, taxiways and apron) with hangars,
    a terminal, a control tower and runway edge lights; one per unit of scale, at least one;
  * a river running north-south across the world with a harbour basin, quays, warehouses and
    cranes beside a port town, and ships on the river and in the basin;
  * an observer path of 240 frames, 100 to 500 m above the ground: over the port town and the
    harbour, up the river past the ships (at 120 m), over a forest, along the runway (at 150 m),
    over a second forest and a town, banked into the turns;
  * three channels (left, centre, right) as airfield.json; daylight sun; haze from 1.5 km, total
    at 20 km, and the background in the fog colour, so that an object past the fog end looks
    exactly like the sky and culling it changes no pixel: the view's visibility range is the fog end.

Coordinates are rounded to 0.01 m and every object is written on one line. Geometry is built so
that this rounding keeps every polygon convex and planar: boxes and roofs are axis-aligned in
their object's frame (the object's heading turns them), sloped decals are cut into triangles.
"""

import argparse
import math
import os
import random
import sys
import tempfile
import time
from array import array

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_airfield import FIELDS, centroid, newell  # noqa: E402  shared with the airfield's generator

# ---------------------------------------------------------------------------------------------
# dimensions and quantities (per unit of scale)

BASE_SIDE = 40000.0            # world side at scale 1 (m); grows with sqrt(scale)
TILE = 1000.0                  # terrain tile (one object)
CELLS = 4                      # cells per tile side (250 m)
CELL = TILE / CELLS
LU = 50.0                      # land-use grid cell
HILL_MAX = 320.0
HOUSES = 5600                  # town buildings per unit of scale
FARMS = 2000
STANDS = 1800                  # forest stands (objects of 4-7 trees)
SHIP_SPACING = 2500.0          # along the river, scaled with the core layout
FRAMES = 240
KEY_STEP = 5
RIVER_HW = 80.0
ROAD_HW = 4.0
STREET_HW = 3.5
BLOCK = 90.0                   # town street pitch
STAND_R, STAND_PITCH = 40.0, 90.0   # forest stand radius, least distance between stands
TREE_SIDES = 4
MAX_SCENE_BYTES = 256 << 20    # cig's limit on scene files
RUNWAY_HALF_L, RUNWAY_HALF_W = 1200.0, 22.5
AIRFIELD_RECT = (-160.0, 430.0, -1450.0, 1450.0)     # runway frame: x0, x1, y0, y1

# core layout (km at scale 1; multiplied by f = min(1, side / 40 km))
CORE_TOWN = (-12.0, 9.0)
CORE_FOREST_A = (-7.5, 6.0, 2.2)
CORE_AIRFIELD = (-2.5, 2.5)
CORE_FOREST_B = (2.0, -1.5, 1.8)
RIVER_X, RIVER_AMP, RIVER_WAVE = 6.5, 1.1, 9.0
HARBOUR_Y = -7.0

# land-use codes
FREE, WATER, AIRFIELD, TOWN, HARBOUR, FOREST, FARM, OUTSIDE = range(8)

# decal heights above the ground (m) and layers
ROAD_Z, WATER_Z = 0.10, 0.05
LAYER_TERRAIN, LAYER_RUNWAY = -2, -1

# colours (linear RGB albedo)
GRASS = (0.30, 0.41, 0.19)
FOREST_FLOOR = (0.13, 0.20, 0.09)
HILL_GREEN = (0.22, 0.30, 0.14)
UPLAND = (0.33, 0.31, 0.20)
TOWN_GROUND = (0.32, 0.35, 0.23)
QUAYSIDE = (0.38, 0.38, 0.36)
WATER_C = (0.15, 0.26, 0.33)
ASPHALT = (0.21, 0.21, 0.22)
CONCRETE = (0.45, 0.45, 0.43)
PAINT_W = (0.92, 0.92, 0.90)
WALLS = [(0.66, 0.60, 0.52), (0.72, 0.70, 0.64), (0.60, 0.52, 0.42), (0.75, 0.72, 0.62), (0.55, 0.50, 0.46)]
ROOFS = [(0.45, 0.20, 0.15), (0.30, 0.28, 0.28), (0.40, 0.26, 0.20), (0.52, 0.30, 0.20)]
CONIFER, BROADLEAF = (0.10, 0.20, 0.09), (0.18, 0.30, 0.11)
CONTAINERS = [(0.60, 0.15, 0.10), (0.12, 0.25, 0.50), (0.15, 0.40, 0.20), (0.70, 0.55, 0.15), (0.50, 0.50, 0.52)]
SUN_AZ, SUN_EL = 210.0, 35.0
FOG = dict(colour=(0.66, 0.71, 0.78), start=1500.0, end=20000.0)
BACKGROUND = FOG['colour']     # the haze: an object past the fog end looks like the sky
LIGHT_WHITE, LIGHT_GREEN = (1.0, 0.96, 0.86), (0.20, 1.0, 0.45)


# ---------------------------------------------------------------------------------------------
# small helpers

def mix(*key):
    """Deterministic 64-bit hash of integers (the same on every platform and Python version)."""
    h = 1469598103934665603
    for k in key:
        h = ((h ^ (int(k) & 0xFFFFFFFFFFFFFFFF)) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
    h ^= h >> 33
    h = (h * 0xFF51AFD7ED558CCD) & 0xFFFFFFFFFFFFFFFF
    return h ^ (h >> 33)


def unit(*key):
    return (mix(*key) >> 11) / float(1 << 53)


def rng_for(*key):
    return random.Random(mix(*key))


def jitter(c, amount, u):
    s = 1.0 + amount * (2.0 * u - 1.0)
    return tuple(min(1.0, max(0.0, v * s)) for v in c)


def smoothstep(t):
    t = min(1.0, max(0.0, t))
    return t * t * (3 - 2 * t)


def rotate(x, y, heading):
    """Object frame (x right, y forward) to world for a heading clockwise from north."""
    h = math.radians(heading)
    c, s = math.cos(h), math.sin(h)
    return x * c + y * s, -x * s + y * c


def unrotate(x, y, heading):
    h = math.radians(heading)
    c, s = math.cos(h), math.sin(h)
    return x * c - y * s, x * s + y * c


def heading_of(dx, dy):
    return math.degrees(math.atan2(dx, dy)) % 360.0


def segment_distance(px, py, ax, ay, bx, by):
    ex, ey = bx - ax, by - ay
    ll = ex * ex + ey * ey
    t = 0.0 if ll == 0 else min(1.0, max(0.0, ((px - ax) * ex + (py - ay) * ey) / ll))
    return math.hypot(px - ax - t * ex, py - ay - t * ey)




def area2d(pts):
    return 0.5 * sum(pts[i - 1][0] * pts[i][1] - pts[i][0] * pts[i - 1][1] for i in range(len(pts)))


def ccw(pts):
    return pts if area2d(pts) > 0 else pts[::-1]


# ---------------------------------------------------------------------------------------------
# 2D convex clipping for decals

def clip_halfplane(pts, ax, ay, bx, by):
    """Keep the part of a polygon on the left of the directed line a -> b."""
    out = []
    ex, ey = bx - ax, by - ay
    prev = pts[-1]
    pd = ex * (prev[1] - ay) - ey * (prev[0] - ax)
    for cur in pts:
        cd = ex * (cur[1] - ay) - ey * (cur[0] - ax)
        if (cd >= 0) != (pd >= 0):
            t = pd / (pd - cd)
            out.append((prev[0] + t * (cur[0] - prev[0]), prev[1] + t * (cur[1] - prev[1])))
        if cd >= 0:
            out.append(cur)
        prev, pd = cur, cd
    return out


def clip_convex(pts, clip):
    """Intersection of a polygon with a convex counter-clockwise polygon."""
    for i in range(len(clip)):
        a, b = clip[i - 1], clip[i]
        pts = clip_halfplane(pts, a[0], a[1], b[0], b[1])
        if len(pts) < 3:
            return []
    return pts


def rect_poly(x0, x1, y0, y1):
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def tidy(pts, min_area=0.2):
    """Round a convex counter-clockwise polygon to 0.01 m and drop the vertices the rounding made
    collinear, repeated or turning the wrong way; None when too little is left."""
    q = []
    for x, y in pts:
        p = (round(x, 2) + 0.0, round(y, 2) + 0.0)
        if not q or p != q[-1]:
            q.append(p)
    while len(q) > 1 and q[0] == q[-1]:
        q.pop()
    changed = True
    while changed and len(q) >= 3:
        changed = False
        for i in range(len(q)):
            a, b, c = q[i - 1], q[i], q[(i + 1) % len(q)]
            e0x, e0y, e1x, e1y = b[0] - a[0], b[1] - a[1], c[0] - b[0], c[1] - b[1]
            l0, l1 = math.hypot(e0x, e0y), math.hypot(e1x, e1y)
            if l0 < 0.02 or l1 < 0.02 or e0x * e1y - e0y * e1x < 2e-3 * l0 * l1:
                del q[i]
                changed = True
                break
    if len(q) < 3 or area2d(q) < min_area:
        return None
    return q


# ---------------------------------------------------------------------------------------------
# scene containers

class Part:
    """A subobject: shared vertices (rounded to 0.01 m) and polygons (indices, own colour)."""
    __slots__ = ('name', 'colour', 'crease', 'verts', 'index', 'polys')

    def __init__(self, name='', colour=None, crease=None):
        self.name, self.colour, self.crease = name, colour, crease
        self.verts, self.index, self.polys = [], {}, []

    def vertex(self, p):
        key = (round(p[0], 2) + 0.0, round(p[1], 2) + 0.0, round(p[2], 2) + 0.0)
        i = self.index.get(key)
        if i is None:
            i = self.index[key] = len(self.verts)
            self.verts.append(key)
        return i

    def face(self, pts, colour=None, out=None):
        """Add a polygon; with `out` its winding is turned so that its front faces that way."""
        if out is not None:
            n = newell(pts)
            if n[0] * out[0] + n[1] * out[1] + n[2] * out[2] < 0:
                pts = pts[::-1]
        idx = [self.vertex(p) for p in pts]
        if len(set(idx)) == len(idx):
            self.polys.append((idx, colour))

    def solid(self, faces, colour_of=None):
        """A convex solid given as faces (point lists), each wound outwards."""
        c = centroid([p for f in faces for p in f])
        for f in faces:
            m = centroid(f)
            self.face(f, colour_of(f) if colour_of else None, (m[0] - c[0], m[1] - c[1], m[2] - c[2]))


class Obj:
    __slots__ = ('name', 'kind', 'pos', 'heading', 'layer', 'by_distance', 'parts', 'lights')

    def __init__(self, name, kind, pos, heading=0.0, layer=0, by_distance=False):
        self.name, self.kind, self.pos, self.heading = name, kind, pos, heading % 360.0
        self.layer, self.by_distance = layer, by_distance
        self.parts, self.lights = [], []

    def part(self, *a, **k):
        p = Part(*a, **k)
        self.parts.append(p)
        return p


# ---------------------------------------------------------------------------------------------
# solids (object coordinates)

def box_faces(x0, x1, y0, y1, z0, z1):
    """A box without its floor."""
    c = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
         (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    return [[c[0], c[1], c[5], c[4]], [c[1], c[2], c[6], c[5]], [c[2], c[3], c[7], c[6]],
            [c[3], c[0], c[4], c[7]], [c[4], c[5], c[6], c[7]]]


def gabled_faces(x0, x1, y0, y1, z0, eaves, ridge):
    """Walls and a gabled roof (ridge along y), without the floor: 2 pentagons and 4 quads."""
    xm = (x0 + x1) / 2
    gable0 = [(x0, y0, z0), (x1, y0, z0), (x1, y0, eaves), (xm, y0, ridge), (x0, y0, eaves)]
    gable1 = [(x, y1, z) for x, _, z in gable0]
    faces = [gable0, gable1]
    for k in range(4):
        a, b = k, k + 1
        faces.append([gable0[a], gable0[b], gable1[b], gable1[a]])
    return faces


def prism_faces(plan, z0, z1):
    """A convex planform extruded from z0 to z1, without the floor."""
    n = len(plan)
    faces = [[(plan[i][0], plan[i][1], z0), (plan[(i + 1) % n][0], plan[(i + 1) % n][1], z0),
              (plan[(i + 1) % n][0], plan[(i + 1) % n][1], z1), (plan[i][0], plan[i][1], z1)] for i in range(n)]
    faces.append([(x, y, z1) for x, y in plan])
    return faces


def is_roof(face):
    n = newell(face)
    length = math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2])
    return n[2] > 0.05 * length


# ---------------------------------------------------------------------------------------------
# the world plan: features, land use, heights, roads

def town_radius(houses):
    """Radius of a town of so many houses (six lots per street block, some to spare)."""
    return math.sqrt(houses * BLOCK * BLOCK / 6.0 / math.pi) * 1.18 + 40.0


class Town:
    def __init__(self, name, x, y, heading, size):
        self.name, self.x, self.y, self.heading, self.size = name, x, y, heading, size
        self.radius = town_radius(size)


class Airfield:
    def __init__(self, name, x, y, heading):
        self.name, self.x, self.y, self.heading = name, x, y, heading

    def to_world(self, lx, ly):
        dx, dy = rotate(lx, ly, self.heading)
        return self.x + dx, self.y + dy

    def rect_distance(self, x, y):
        lx, ly = unrotate(x - self.x, y - self.y, self.heading)
        x0, x1, y0, y1 = AIRFIELD_RECT
        return math.hypot(max(x0 - lx, 0.0, lx - x1), max(y0 - ly, 0.0, ly - y1))


class World:
    def __init__(self, scale, seed):
        self.scale, self.seed = scale, seed
        self.tiles = max(4, int(round(BASE_SIDE / TILE * math.sqrt(scale))))
        self.side = self.tiles * TILE
        self.half = self.side / 2
        self.f = min(1.0, self.side / BASE_SIDE)
        self.nv = self.tiles * CELLS + 1
        self.nl = int(round(self.side / LU))
        self.landuse = bytearray(self.nl * self.nl)
        self.flat = array('d', [1.0]) * (self.nv * self.nv)
        self.heights = array('d', [0.0]) * (self.nv * self.nv)
        self.towns, self.airfields, self.roads, self.stands, self.farms, self.ships = [], [], [], [], [], []
        self.river, self.river_phase, self.harbour = [], 0.0, None
        self.road_index, self.forest_cells, self.decals = {}, set(), {}

    def core(self, x_km, y_km):
        return x_km * 1000.0 * self.f, y_km * 1000.0 * self.f

    def inside(self, x, y, margin):
        return abs(x) <= self.half - margin and abs(y) <= self.half - margin

    # land use -----------------------------------------------------------------------------
    def use_at(self, x, y):
        i, j = int((x + self.half) // LU), int((y + self.half) // LU)
        if 0 <= i < self.nl and 0 <= j < self.nl:
            return self.landuse[j * self.nl + i]
        return OUTSIDE

    def mark(self, code, bbox, inside, overwrite=False):
        x0, x1, y0, y1 = bbox
        i0, i1 = max(0, int((x0 + self.half) // LU)), min(self.nl - 1, int((x1 + self.half) // LU))
        j0, j1 = max(0, int((y0 + self.half) // LU)), min(self.nl - 1, int((y1 + self.half) // LU))
        for j in range(j0, j1 + 1):
            y = -self.half + (j + 0.5) * LU
            row = j * self.nl
            for i in range(i0, i1 + 1):
                if (overwrite or not self.landuse[row + i]) and inside(-self.half + (i + 0.5) * LU, y):
                    self.landuse[row + i] = code

    def area_free(self, x, y, r, allowed=(FREE,)):
        return all(self.use_at(x + dx, y + dy) in allowed
                   for dx, dy in ((0, 0), (r, 0), (-r, 0), (0, r), (0, -r)))

    # terrain --------------------------------------------------------------------------------
    def vertex_xy(self, i, j):
        return -self.half + i * CELL, -self.half + j * CELL

    def flatten(self, bbox, dist, d0, ramp):
        """Level the terrain within d0 of a feature, rising over `ramp` metres beyond."""
        x0, x1, y0, y1 = bbox
        reach = d0 + ramp
        i0 = max(0, int((x0 - reach + self.half) // CELL))
        i1 = min(self.nv - 1, int((x1 + reach + self.half) // CELL) + 1)
        j0 = max(0, int((y0 - reach + self.half) // CELL))
        j1 = min(self.nv - 1, int((y1 + reach + self.half) // CELL) + 1)
        for j in range(j0, j1 + 1):
            y = -self.half + j * CELL
            for i in range(i0, i1 + 1):
                d = dist(-self.half + i * CELL, y)
                if d < reach:
                    s = smoothstep((d - d0) / ramp)
                    k = j * self.nv + i
                    if s < self.flat[k]:
                        self.flat[k] = s

    def z_at_vertex(self, i, j):
        return self.heights[j * self.nv + i]

    def ground_z(self, x, y):
        """Height of the triangulated terrain surface."""
        fx = min(max((x + self.half) / CELL, 0.0), self.nv - 1.000001)
        fy = min(max((y + self.half) / CELL, 0.0), self.nv - 1.000001)
        i, j = int(fx), int(fy)
        u, v = fx - i, fy - j
        za, zb = self.z_at_vertex(i, j), self.z_at_vertex(i + 1, j)
        zc, zd = self.z_at_vertex(i + 1, j + 1), self.z_at_vertex(i, j + 1)
        if split_ac(za, zb, zc, zd):
            return za + u * (zb - za) + v * (zc - zb) if u >= v else za + u * (zc - zd) + v * (zd - za)
        return za + u * (zb - za) + v * (zd - za) if u + v <= 1 else \
            zc + (1 - u) * (zd - zc) + (1 - v) * (zb - zc)

    # roads ----------------------------------------------------------------------------------
    def road_clearance(self, x, y):
        """Distance from a point to the edge of the nearest road (inf if none near)."""
        best = math.inf
        for ax, ay, bx, by, hw in self.road_index.get((int((x + self.half) // TILE), int((y + self.half) // TILE)), ()):
            best = min(best, segment_distance(x, y, ax, ay, bx, by) - hw)
        return best

    def add_decal(self, kind, pts):
        """A convex world polygon lying on the terrain, filed under every tile its box touches."""
        pts = ccw(pts)
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        i0, i1 = max(0, int((min(xs) + self.half) // TILE)), min(self.tiles - 1, int((max(xs) + self.half) // TILE))
        j0, j1 = max(0, int((min(ys) + self.half) // TILE)), min(self.tiles - 1, int((max(ys) + self.half) // TILE))
        for j in range(j0, j1 + 1):
            for i in range(i0, i1 + 1):
                self.decals.setdefault((i, j), []).append((kind, pts))


def split_ac(za, zb, zc, zd):
    """A cell is split along a-c (south-west to north-east) unless b-d is the flatter diagonal."""
    return abs(za - zc) <= abs(zb - zd)


# river and harbour ------------------------------------------------------------------------------

def river_x(world, y):
    f = world.f
    a, lam = RIVER_AMP * 1000 * f, RIVER_WAVE * 1000 * f
    return RIVER_X * 1000 * f + a * math.sin(2 * math.pi * y / lam + world.river_phase) \
        + 0.3 * a * math.sin(2 * math.pi * y / (3.7 * lam) + 1.3 * world.river_phase)


def plan_river(world, rng):
    world.river_phase = rng.uniform(0, 2 * math.pi)
    step = 100.0
    n = int(math.ceil((world.side + 1000) / step))
    world.river = [(river_x(world, -world.half - 500 + k * step), -world.half - 500 + k * step) for k in range(n + 1)]
    for (ax, ay), (bx, by) in zip(world.river, world.river[1:]):
        box = (min(ax, bx) - RIVER_HW - 40, max(ax, bx) + RIVER_HW + 40, ay, by)
        world.mark(WATER, box, lambda x, y, a=(ax, ay, bx, by): segment_distance(x, y, *a) < RIVER_HW + 30)
        world.flatten(box, lambda x, y, a=(ax, ay, bx, by): segment_distance(x, y, *a), RIVER_HW + 250, 1000)


def river_sections(world):
    """Left and right bank points of each river cross-section."""
    out = []
    pts = world.river
    for k, (x, y) in enumerate(pts):
        a, b = pts[max(0, k - 1)], pts[min(len(pts) - 1, k + 1)]
        tx, ty = b[0] - a[0], b[1] - a[1]
        ln = math.hypot(tx, ty)
        nx, ny = -ty / ln, tx / ln
        out.append(((x + nx * RIVER_HW, y + ny * RIVER_HW), (x - nx * RIVER_HW, y - ny * RIVER_HW)))
    return out


def plan_harbour(world):
    """A basin on the west bank at the river's westmost bend near HARBOUR_Y, quays and sheds."""
    f, g = world.f, max(0.5, world.f)
    lam = RIVER_WAVE * 1000 * f
    y_target = HARBOUR_Y * 1000 * f
    ys = [y_target - lam / 2 + lam * k / 200 for k in range(201)]
    yh = min(ys, key=lambda y: river_x(world, y))
    length, width = 700.0 * g, 380.0 * g
    bank = max(river_x(world, yh + length * (k / 20.0 - 0.5)) for k in range(21)) - RIVER_HW
    xe = bank + 25.0
    basin = (xe - width, xe, yh - length / 2, yh + length / 2)
    zone = (basin[0] - 170.0, basin[1], basin[2] - 60.0, basin[3] + 60.0)
    world.harbour = dict(basin=basin, zone=zone, y=yh)
    world.mark(HARBOUR, zone, lambda x, y: rect_distance(x, y, zone) == 0, overwrite=True)
    world.flatten(zone, lambda x, y: rect_distance(x, y, zone), 200, 1000)
    world.add_decal('water', rect_poly(*basin))


def rect_distance(x, y, r):
    return math.hypot(max(r[0] - x, 0.0, x - r[1]), max(r[2] - y, 0.0, y - r[3]))


def river_distance(world, x, y):
    return abs(x - river_x(world, y))


# airfields and towns ---------------------------------------------------------------------------

def airfield_fits(world, x, y):
    """Far enough from the river, the harbour, the core town and the other airfields."""
    town = world.core(*CORE_TOWN)
    return river_distance(world, x, y) >= 3000 and \
        rect_distance(x, y, world.harbour['zone']) >= 5000 and \
        math.hypot(x - town[0], y - town[1]) >= 4500 and \
        all(math.hypot(x - a.x, y - a.y) >= 8000 for a in world.airfields)


def plan_airfields(world, rng):
    """The core airfield, then more at random places: one per unit of scale."""
    count = max(1, int(round(world.scale)))
    x, y = world.core(*CORE_AIRFIELD)
    add_airfield(world, x, y, rng.uniform(0, 180.0))
    m = 2500.0
    for _ in range(400 * count):
        if len(world.airfields) >= count:
            break
        x, y = rng.uniform(-world.half + m, world.half - m), rng.uniform(-world.half + m, world.half - m)
        if airfield_fits(world, x, y):
            add_airfield(world, x, y, rng.uniform(0, 360.0))


def add_airfield(world, x, y, heading):
    a = Airfield('airfield_%d' % (len(world.airfields) + 1), x, y, heading)
    world.airfields.append(a)
    r = math.hypot(1500, 450)
    box = (x - r, x + r, y - r, y + r)
    world.mark(AIRFIELD, box, lambda px, py: a.rect_distance(px, py) <= 0, overwrite=True)
    world.flatten(box, a.rect_distance, 150, 1200)


def town_fits(world, x, y, r):
    if not world.inside(x, y, r + 400):
        return False
    if river_distance(world, x, y) < r + 600:
        return False
    if any(math.hypot(x - t.x, y - t.y) < r + t.radius + 1200 for t in world.towns):
        return False
    if any(math.hypot(x - a.x, y - a.y) < r + 2000 for a in world.airfields):
        return False
    z = world.harbour['zone']
    if rect_distance(x, y, z) < r + 300:
        return False
    return all(world.use_at(x + r * math.cos(a), y + r * math.sin(a)) == FREE
               for a in [k * math.pi / 4 for k in range(8)]) and world.use_at(x, y) == FREE


def plan_towns(world, rng):
    target = int(round(HOUSES * world.scale))
    core_size = max(12, min(550, target // 2))
    x, y = world.core(*CORE_TOWN)
    add_town(world, x, y, rng.uniform(0, 90.0), core_size)
    add_town(world, world.harbour['zone'][0] - town_radius(core_size) - 120.0, world.harbour['y'], 0.0, core_size)
    total, tries = 2 * core_size, 0
    while total < target and tries < 2000 + target:
        tries += 1
        size = min(target - total, int(rng.uniform(200, 800)))
        if target - total - size < 60:
            size = target - total
        r = town_radius(size)
        x, y = rng.uniform(-world.half, world.half), rng.uniform(-world.half, world.half)
        if town_fits(world, x, y, r):
            add_town(world, x, y, rng.uniform(0, 90.0), size)
            total += size


def add_town(world, x, y, heading, size):
    t = Town('town_%d' % (len(world.towns) + 1), x, y, heading, size)
    world.towns.append(t)
    r = t.radius + 60
    box = (x - r, x + r, y - r, y + r)
    world.mark(TOWN, box, lambda px, py: math.hypot(px - x, py - y) <= r)
    world.flatten(box, lambda px, py: math.hypot(px - x, py - y), t.radius + 250, 1200)


# heights ----------------------------------------------------------------------------------------

def make_waves(rng):
    waves = []
    for _ in range(7):
        lam = rng.uniform(2500, 14000)
        th = rng.uniform(0, 2 * math.pi)
        waves.append((2 * math.pi * math.cos(th) / lam, 2 * math.pi * math.sin(th) / lam,
                      rng.uniform(0, 2 * math.pi), lam ** 0.7))
    total = sum(w[3] for w in waves)
    return [(kx, ky, ph, a / total) for kx, ky, ph, a in waves]


def hill_height(waves, x, y):
    n = 0.0
    for kx, ky, ph, a in waves:
        n += a * math.sin(kx * x + ky * y + ph)
    return HILL_MAX * smoothstep((n + 0.15) / 0.65)


def compute_heights(world, rng):
    waves = make_waves(rng)
    for j in range(world.nv):
        for i in range(world.nv):
            k = j * world.nv + i
            m = world.flat[k]
            if m > 0.0:
                x, y = world.vertex_xy(i, j)
                h = round(hill_height(waves, x, y) * m, 2)
                world.heights[k] = h if h >= 0.05 else 0.0


# roads ------------------------------------------------------------------------------------------

def road_blocked(world, ax, ay, bx, by):
    n = max(1, int(math.hypot(bx - ax, by - ay) / 20.0))
    for k in range(n + 1):
        x, y = ax + (bx - ax) * k / n, ay + (by - ay) * k / n
        if world.use_at(x, y) in (AIRFIELD, HARBOUR, OUTSIDE):
            return True
    return False


def plan_roads(world):
    towns = world.towns
    pairs = set()
    for a, t in enumerate(towns):
        near = sorted(range(len(towns)), key=lambda b: math.hypot(towns[b].x - t.x, towns[b].y - t.y))
        for b in near[1:3]:
            pairs.add((min(a, b), max(a, b)))
    for a, b in sorted(pairs):
        ta, tb = towns[a], towns[b]
        if not road_blocked(world, ta.x, ta.y, tb.x, tb.y):
            add_road(world, ta.x, ta.y, tb.x, tb.y, ROAD_HW)
    for af in world.airfields:
        gx, gy = af.to_world(AIRFIELD_RECT[1] + 15.0, 0.0)
        for t in sorted(towns, key=lambda t: math.hypot(t.x - gx, t.y - gy)):
            if not road_blocked(world, gx, gy, t.x, t.y):
                add_road(world, gx, gy, t.x, t.y, ROAD_HW)
                break


def add_road(world, ax, ay, bx, by, hw):
    """A straight road: filed for clearance checks and cut into decal strips of at most 400 m."""
    world.roads.append((ax, ay, bx, by, hw))
    m = 40.0
    for j in range(int((min(ay, by) - m + world.half) // TILE), int((max(ay, by) + m + world.half) // TILE) + 1):
        for i in range(int((min(ax, bx) - m + world.half) // TILE), int((max(ax, bx) + m + world.half) // TILE) + 1):
            if segment_distance(-world.half + (i + 0.5) * TILE, -world.half + (j + 0.5) * TILE, ax, ay, bx, by) \
                    < TILE * 0.75 + m:
                world.road_index.setdefault((i, j), []).append((ax, ay, bx, by, hw))
    add_strip(world, 'roads', ax, ay, bx, by, hw)


def add_strip(world, kind, ax, ay, bx, by, hw):
    length = math.hypot(bx - ax, by - ay)
    if length < 1.0:
        return
    nx, ny = -(by - ay) / length * hw, (bx - ax) / length * hw
    n = max(1, int(math.ceil(length / 400.0)))
    for k in range(n):
        px, py = ax + (bx - ax) * k / n, ay + (by - ay) * k / n
        qx, qy = ax + (bx - ax) * (k + 1) / n, ay + (by - ay) * (k + 1) / n
        world.add_decal(kind, [(px + nx, py + ny), (px - nx, py - ny), (qx - nx, qy - ny), (qx + nx, qy + ny)])


def plan_streets(world, town):
    """The town's street grid (chords of its disc every BLOCK metres), as road decals."""
    r = town.radius
    k = int(r // BLOCK)
    for a in range(-k, k + 1):
        u = a * BLOCK
        half = math.sqrt(max(0.0, r * r - u * u))
        if half < 60:
            continue
        for ends in (((u, -half), (u, half)), ((-half, u), (half, u))):
            (p, q) = [rotate(x, y, town.heading) for x, y in ends]
            add_strip(world, 'roads', town.x + p[0], town.y + p[1], town.x + q[0], town.y + q[1], STREET_HW)


def plan_water(world):
    secs = river_sections(world)
    for (l0, r0), (l1, r1) in zip(secs, secs[1:]):
        world.add_decal('water', [r0, r1, l1, l0])


# forests, farms, ships --------------------------------------------------------------------------

def forest_region(world, rng, core):
    """Centre and radius of the next forest: the core ones first, then the highest of three
    random places (forests grow mostly on the hills)."""
    if core:
        x, y = world.core(core[0][0], core[0][1])
        return x, y, core.pop(0)[2] * 1000 * world.f
    places = [(rng.uniform(-world.half, world.half), rng.uniform(-world.half, world.half)) for _ in range(3)]
    x, y = max(places, key=lambda p: world.ground_z(*p))
    return x, y, rng.uniform(700, 1800)


def plan_forests(world, rng):
    target = int(round(STANDS * world.scale))
    core = [CORE_FOREST_A, CORE_FOREST_B]
    taken = {}
    tries = 0
    while len(world.stands) < target and tries < 50 + 20 * target:
        tries += 1
        x, y, radius = forest_region(world, rng, core)
        capacity = int(math.pi * radius * radius / (STAND_PITCH * STAND_PITCH) * 0.6)
        want = min(capacity, target - len(world.stands))
        for _ in range(want * 4):
            tries += 1
            a, r = rng.uniform(0, 2 * math.pi), radius * math.sqrt(rng.random())
            sx, sy = x + r * math.cos(a), y + r * math.sin(a)
            if add_stand(world, sx, sy, taken):
                want -= 1
                if want == 0:
                    break


def add_stand(world, x, y, taken):
    if not world.inside(x, y, 150) or not world.area_free(x, y, STAND_R, (FREE, FOREST)):
        return False
    key = (int(x // STAND_PITCH), int(y // STAND_PITCH))
    for dj in (-1, 0, 1):
        for di in (-1, 0, 1):
            q = taken.get((key[0] + di, key[1] + dj))
            if q and math.hypot(q[0] - x, q[1] - y) < 0.9 * STAND_PITCH:
                return False
    if key in taken:
        return False
    taken[key] = (x, y)
    world.stands.append((x, y))
    r = STAND_R + 10
    world.mark(FOREST, (x - r, x + r, y - r, y + r), lambda px, py: math.hypot(px - x, py - y) < r)
    world.forest_cells.add((int((x + world.half) // CELL), int((y + world.half) // CELL)))
    return True


def plan_farms(world, rng):
    target = int(round(FARMS * world.scale))
    tries = 0
    while len(world.farms) < target and tries < 40 * target + 100:
        tries += 1
        x, y = rng.uniform(-world.half, world.half), rng.uniform(-world.half, world.half)
        if not world.inside(x, y, 120) or not world.area_free(x, y, 40.0):
            continue
        if world.road_clearance(x, y) < 30:
            continue
        corners = [world.ground_z(x + dx, y + dy) for dx in (-30, 30) for dy in (-30, 30)]
        if max(corners) - min(corners) > 6.0:
            continue
        world.farms.append((x, y, rng.uniform(0, 90.0), min(corners), max(corners)))
        world.mark(FARM, (x - 40, x + 40, y - 40, y + 40), lambda px, py: math.hypot(px - x, py - y) < 40)


def plan_ships(world, rng):
    """Ships along the river (both directions, two lanes) and moored in the harbour basin."""
    step = SHIP_SPACING * world.f
    y = -world.half + step * rng.uniform(0.2, 0.8)
    basin = world.harbour['basin']
    while y < world.half - 300:
        if not basin[2] - 200 <= y <= basin[3] + 200:
            up = rng.random() < 0.5
            x0, x1 = river_x(world, y - 10), river_x(world, y + 10)
            hd = heading_of(x1 - x0, 20.0)
            lane = RIVER_HW * 0.4 * (1 if up else -1)
            nx, ny = rotate(1.0, 0.0, hd)
            kind = rng.choice(['cargo', 'cargo', 'tanker', 'ferry', 'tug', 'barge'])
            world.ships.append((kind, river_x(world, y) + nx * lane, y + ny * lane, (hd + (180 if up else 0)) % 360))
        y += step * rng.uniform(0.7, 1.3)
    y = basin[2] + 15.0
    for k, kind in enumerate(['cargo', 'ferry', 'tanker', 'tug']):
        length, beam = SHIP_TYPES[kind][:2]
        if y + length > basin[3] - 15.0:
            break
        world.ships.append((kind, basin[0] + beam / 2 + 3.0, y + length / 2, 0.0 if k % 2 else 180.0))
        y += length + 15.0


def plan_world(scale, seed):
    world = World(scale, seed)
    plan_river(world, rng_for(seed, 1))
    plan_harbour(world)
    plan_airfields(world, rng_for(seed, 2))
    plan_towns(world, rng_for(seed, 3))
    compute_heights(world, rng_for(seed, 4))
    plan_roads(world)
    for t in world.towns:
        plan_streets(world, t)
    plan_water(world)
    plan_forests(world, rng_for(seed, 5))
    plan_farms(world, rng_for(seed, 6))
    plan_ships(world, rng_for(seed, 7))
    return world


# ---------------------------------------------------------------------------------------------
# terrain tiles: ground cells and the decals draped over them

def ground_faces(world, ti, tj, cx, cy):
    """Per cell of the tile: its faces in tile coordinates, each (points, flat)."""
    cells = {}
    for cj in range(CELLS):
        for ci in range(CELLS):
            i, j = ti * CELLS + ci, tj * CELLS + cj
            x0, y0 = world.vertex_xy(i, j)
            x0, y0 = x0 - cx, y0 - cy
            x1, y1 = x0 + CELL, y0 + CELL
            za, zb = world.z_at_vertex(i, j), world.z_at_vertex(i + 1, j)
            zc, zd = world.z_at_vertex(i + 1, j + 1), world.z_at_vertex(i, j + 1)
            a, b, c, d = (x0, y0, za), (x1, y0, zb), (x1, y1, zc), (x0, y1, zd)
            if za == zb == zc == zd == 0.0:
                cells[(ci, cj)] = [([a, b, c, d], True)]
            elif split_ac(za, zb, zc, zd):
                cells[(ci, cj)] = [([a, b, c], False), ([a, c, d], False)]
            else:
                cells[(ci, cj)] = [([a, b, d], False), ([b, c, d], False)]
    return cells


def cell_colour(world, i, j, faces):
    x, y = world.vertex_xy(i, j)
    x, y = x + CELL / 2, y + CELL / 2
    use = world.use_at(x, y)
    u = unit(world.seed, i, j, 7)
    if use == AIRFIELD:
        return jitter(GRASS, 0.05, u)
    if use == HARBOUR:
        return jitter(QUAYSIDE, 0.05, u)
    if use == TOWN:
        return jitter(TOWN_GROUND, 0.08, u)
    if (i, j) in world.forest_cells:
        return jitter(FOREST_FLOOR, 0.12, u)
    z = max(p[2] for f, _ in faces for p in f)
    if z < 40.0:
        return jitter(FIELDS[int(unit(world.seed, i, j, 3) * len(FIELDS))], 0.08, u)
    return jitter(HILL_GREEN if z < 220.0 else UPLAND, 0.10, u)


def plane_of(face):
    """z(x, y) of the plane through a terrain triangle."""
    p0, p1, p2 = face
    ux, uy, uz = p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]
    vx, vy, vz = p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]
    nx, ny, nz = uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx
    return lambda x, y: p0[2] - (nx * (x - p0[0]) + ny * (y - p0[1])) / nz


def lay_flat(part, pts, z):
    pts = tidy(pts)
    if not pts:
        return
    if len(pts) > 11:
        for k in range(1, len(pts) - 1):
            part.face([(pts[0][0], pts[0][1], z), (pts[k][0], pts[k][1], z), (pts[k + 1][0], pts[k + 1][1], z)])
        return
    part.face([(x, y, z) for x, y in pts])


def lay_sloped(part, pts, plane, dz):
    """A decal piece on a terrain triangle: its vertices lifted onto the plane, cut into a fan."""
    pts = tidy(pts)
    if not pts:
        return
    lifted = [(x, y, round(plane(x, y) + dz, 2)) for x, y in pts]
    for k in range(1, len(lifted) - 1):
        tri = [lifted[0], lifted[k], lifted[k + 1]]
        if area2d(tri) > 0.05:
            part.face(tri)


def drape(part, cells, pts, dz):
    """Lay a decal (tile coordinates) over the tile's ground faces."""
    h = TILE / 2
    piece = clip_convex(pts, rect_poly(-h, h, -h, h))
    if not piece:
        return
    xs, ys = [p[0] for p in piece], [p[1] for p in piece]
    ci0, ci1 = max(0, int((min(xs) + h) // CELL)), min(CELLS - 1, int((max(xs) + h) // CELL))
    cj0, cj1 = max(0, int((min(ys) + h) // CELL)), min(CELLS - 1, int((max(ys) + h) // CELL))
    under = [cells[(ci, cj)] for cj in range(cj0, cj1 + 1) for ci in range(ci0, ci1 + 1)]
    if all(faces[0][1] for faces in under):
        lay_flat(part, piece, dz)
        return
    for faces in under:
        for face, flat in faces:
            sub = clip_convex(piece, [(p[0], p[1]) for p in face])
            if not sub:
                continue
            if flat:
                lay_flat(part, sub, dz)
            else:
                lay_sloped(part, sub, plane_of(face), dz)


def build_tile(world, ti, tj):
    cx, cy = -world.half + (ti + 0.5) * TILE, -world.half + (tj + 0.5) * TILE
    o = Obj('tile_%d_%d' % (ti, tj), 'terrain', (cx, cy, 0.0), layer=LAYER_TERRAIN)
    cells = ground_faces(world, ti, tj, cx, cy)
    decals = world.decals.get((ti, tj), [])
    for kind, colour, dz in (('roads', ASPHALT, ROAD_Z), ('water', WATER_C, WATER_Z)):
        part = Part(kind, colour, 0)
        for k, pts in decals:
            if k == kind:
                drape(part, cells, [(x - cx, y - cy) for x, y in pts], dz)
        if part.polys:
            o.parts.append(part)
    ground = o.part('ground', None, 70)
    for (ci, cj), faces in sorted(cells.items(), key=lambda kv: (kv[0][1], kv[0][0])):
        col = cell_colour(world, ti * CELLS + ci, tj * CELLS + cj, faces)
        for face, _ in faces:
            ground.face(face, col)
    return o


# ---------------------------------------------------------------------------------------------
# towns and farms

def house_lots(town):
    """Lot centres (town frame) nearest the centre first: 3 x 2 lots per street block."""
    inner = BLOCK - 2 * STREET_HW
    lw, ld = inner / 3.0, inner / 2.0
    k = int(town.radius // BLOCK) + 1
    lots = []
    for b in range(-k, k):
        for a in range(-k, k):
            for j in range(2):
                for i in range(3):
                    u = a * BLOCK + STREET_HW + (i + 0.5) * lw
                    v = b * BLOCK + STREET_HW + (j + 0.5) * ld
                    if math.hypot(u, v) <= town.radius - 25:
                        lots.append((math.hypot(u, v), u, v, j))
    lots.sort()
    return lots


def build_town(world, town):
    rng = rng_for(world.seed, 100, world.towns.index(town))
    built = 0
    for dist, u, v, row in house_lots(town):
        if built >= town.size:
            break
        du, dv = rotate(u, v, town.heading)
        x, y = town.x + du, town.y + dv
        if world.road_clearance(x, y) < 14 or world.use_at(x, y) not in (TOWN, FREE):
            continue
        centre = dist < 0.3 * town.radius
        yield town_building(world, '%s_h%d' % (town.name, built), x, y, town.heading + (180 if row else 0),
                            centre, rng)
        built += 1


def town_building(world, name, x, y, heading, centre, rng):
    z = world.ground_z(x, y)
    o = Obj(name, 'town', (x, y, z), heading)
    wall = jitter(rng.choice(WALLS), 0.10, rng.random())
    roof = jitter(rng.choice(ROOFS), 0.08, rng.random())
    jx, jy = rng.uniform(-2.5, 2.5), rng.uniform(-2.5, 2.5)
    if centre:
        w, d, h = rng.uniform(14, 20), rng.uniform(16, 26), rng.uniform(9, 18)
        faces = box_faces(jx - w / 2, jx + w / 2, jy - d / 2, jy + d / 2, 0.0, h)
        o.part('block', wall, 0).solid(faces, lambda f: (0.34, 0.33, 0.32) if is_roof(f) else None)
    else:
        w, d = rng.uniform(8, 12), rng.uniform(9, 14)
        eaves = rng.uniform(4.5, 6.5)
        faces = gabled_faces(jx - w / 2, jx + w / 2, jy - d / 2, jy + d / 2, 0.0, eaves, eaves + rng.uniform(2.5, 4))
        o.part('house', wall, 0).solid(faces, lambda f: roof if is_roof(f) else None)
    return o


def build_farm(world, k):
    x, y, heading, zmin, zmax = world.farms[k]
    rng = rng_for(world.seed, 200, k)
    o = Obj('farm_%d' % k, 'farm', (x, y, zmin - 0.3), heading, by_distance=True)
    rise = zmax - zmin + 0.3
    w, d = rng.uniform(8, 11), rng.uniform(10, 13)
    wall = jitter(rng.choice(WALLS), 0.1, rng.random())
    house = gabled_faces(-12 - w / 2, -12 + w / 2, -d / 2, d / 2, 0.0, 5.0 + rise, 8.0 + rise)
    roof = jitter(rng.choice(ROOFS), 0.08, rng.random())
    o.part('farmhouse', wall, 0).solid(house, lambda f: roof if is_roof(f) else None)
    bw, bd = rng.uniform(12, 16), rng.uniform(20, 28)
    barn_c = jitter((0.45, 0.18, 0.12) if rng.random() < 0.6 else (0.50, 0.50, 0.48), 0.1, rng.random())
    barn = gabled_faces(8, 8 + bw, -bd / 2, bd / 2, 0.0, 5.5 + rise, 10.0 + rise)
    o.part('barn', barn_c, 0).solid(barn, lambda f: (0.30, 0.30, 0.31) if is_roof(f) else None)
    return o


# ---------------------------------------------------------------------------------------------
# forests

def ring(x, y, r, z, n, phase):
    return [(x + r * math.cos(phase + 2 * math.pi * k / n), y + r * math.sin(phase + 2 * math.pi * k / n), z)
            for k in range(n)]


def tree(part, x, y, z0, rng):
    """A conifer (four-sided cone) or a broadleaf tree (four-sided double pyramid)."""
    h = rng.uniform(12, 22)
    phase = rng.uniform(0, 2 * math.pi)
    conifer = rng.random() < 0.6
    if not conifer:
        part.colour = jitter(BROADLEAF, 0.15, rng.random())
    rim = ring(x, y, h * 0.3, z0 - 0.5, TREE_SIDES, phase) if conifer else \
        ring(x, y, h * 0.4, z0 + h * 0.5, TREE_SIDES, phase)
    top, foot = (x, y, z0 + h), (x, y, z0 + 1.5)
    for k in range(TREE_SIDES):
        p, q = rim[k], rim[(k + 1) % TREE_SIDES]
        side = (p[0] + q[0] - 2 * x, p[1] + q[1] - 2 * y)
        part.face([p, q, top], out=side + (1.0,))
        if not conifer:
            part.face([q, p, foot], out=side + (-1.0,))


def build_stand(world, k):
    sx, sy = world.stands[k]
    rng = rng_for(world.seed, 300, k)
    o = Obj('forest_%d' % k, 'forest', (round(sx, 2), round(sy, 2), 0.0), by_distance=True)
    placed = []
    want = rng.randint(4, 7)
    for _ in range(want * 8):
        if len(placed) == want:
            break
        a, r = rng.uniform(0, 2 * math.pi), STAND_R * math.sqrt(rng.random())
        x, y = sx + r * math.cos(a), sy + r * math.sin(a)
        if any(math.hypot(x - px, y - py) < 8 for px, py in placed):
            continue
        if world.use_at(x, y) not in (FREE, FOREST) or world.road_clearance(x, y) < 6:
            continue
        placed.append((x, y))
        part = o.part('', jitter(CONIFER, 0.15, rng.random()), 75)
        tree(part, x - o.pos[0], y - o.pos[1], world.ground_z(x, y), rng)
    return o if o.parts else None


# ---------------------------------------------------------------------------------------------
# airfields

def runway_markings(part):
    """Piano keys, aiming points, centreline dashes and edge lines (runway frame, z 0.15)."""
    z = 0.15
    rects = []
    for sgn in (-1, 1):
        end = sgn * RUNWAY_HALF_L
        for k in range(6):
            x = 2.7 + 3.6 * k
            for side in (-1, 1):
                a, b = sorted((end - sgn * 6.0, end - sgn * 36.0))
                rects.append((side * x - 0.9, side * x + 0.9, a, b))
        for side in (-1, 1):
            a, b = sorted((end - sgn * 400.0, end - sgn * 460.0))
            rects.append(tuple(sorted((side * 6.0, side * 15.0))) + (a, b))
    y = -RUNWAY_HALF_L + 70.0
    while y + 30 <= RUNWAY_HALF_L - 70.0:
        rects.append((-0.45, 0.45, y, y + 30))
        y += 50.0
    for side in (-1, 1):
        a, b = sorted((side * 21.0, side * 21.9))
        for k in range(8):
            rects.append((a, b, -RUNWAY_HALF_L + 300 * k, -RUNWAY_HALF_L + 300 * (k + 1)))
    for x0, x1, y0, y1 in rects:
        part.face([(x0, y0, z), (x1, y0, z), (x1, y1, z), (x0, y1, z)])


def flat_rect(part, x0, x1, y0, y1, z, colour=None):
    part.face([(x0, y0, z), (x1, y0, z), (x1, y1, z), (x0, y1, z)], colour)


def build_runway(world, af):
    o = Obj(af.name + '_runway', 'airfield', (af.x, af.y, 0.0), af.heading, layer=LAYER_RUNWAY)
    runway_markings(o.part('markings', PAINT_W, 0))
    s = o.part('runway', ASPHALT, 0)
    for k in range(8):
        y0 = -RUNWAY_HALF_L + 300 * k
        flat_rect(s, -RUNWAY_HALF_W, RUNWAY_HALF_W, y0, y0 + 300, 0.10, jitter(ASPHALT, 0.05, unit(world.seed, k, 9)))
    t = o.part('taxiways', (0.25, 0.25, 0.26), 0)
    for k in range(6):
        y0 = -RUNWAY_HALF_L + 400 * k
        flat_rect(t, 138.5, 161.5, y0, y0 + 400, 0.10)
    for yc in (-RUNWAY_HALF_L + 20, 0.0, RUNWAY_HALF_L - 20):
        flat_rect(t, RUNWAY_HALF_W, 138.5, yc - 11.5, yc + 11.5, 0.10)
    a = o.part('apron', CONCRETE, 0)
    for k in range(5):
        flat_rect(a, 161.5, 360.0, -250.0 + 100 * k, -150.0 + 100 * k, 0.10)
    return o


def airfield_building(af, name, lx, ly, faces_by_part):
    x, y = af.to_world(lx, ly)
    o = Obj('%s_%s' % (af.name, name), 'airfield', (x, y, 0.0), af.heading)
    for pname, colour, faces, roof in faces_by_part:
        o.part(pname, colour, 0).solid(faces, (lambda f, r=roof: r if is_roof(f) else None) if roof else None)
    return o


def build_airfield(world, af):
    yield build_runway(world, af)
    for k, yc in enumerate((-190.0, -110.0, -30.0)):
        body = gabled_faces(-25, 25, -35, 35, 0.0, 12.0, 17.0)
        yield airfield_building(af, 'hangar_%d' % (k + 1), 390.0, yc - 20, [('hangar', (0.52, 0.54, 0.56), body,
                                                                            (0.40, 0.42, 0.45))])
    yield airfield_building(af, 'terminal', 395.0, 80.0, [('terminal', (0.60, 0.58, 0.55),
                                                          box_faces(-20, 20, -40, 40, 0.0, 12.0), (0.35, 0.35, 0.36))])
    yield airfield_building(af, 'tower', 390.0, 170.0, [
        ('cab', (0.30, 0.42, 0.40), box_faces(-5, 5, -5, 5, 24.0, 28.0), (0.35, 0.35, 0.37)),
        ('shaft', (0.62, 0.60, 0.56), box_faces(-2.5, 2.5, -2.5, 2.5, 0.0, 24.0), None)])
    yield runway_lights(af)


def runway_lights(af):
    o = Obj(af.name + '_lights', 'airfield', (af.x, af.y, 0.0), af.heading)
    for k in range(41):
        y = -RUNWAY_HALF_L + 60 * k
        for x in (-RUNWAY_HALF_W - 1.5, RUNWAY_HALF_W + 1.5):
            o.lights.append(((x, y, 0.4), LIGHT_WHITE, 2.0))
    for sgn in (-1, 1):
        for k in range(12):
            o.lights.append(((-20.0 + 40.0 * k / 11, sgn * (RUNWAY_HALF_L + 3.0), 0.4), LIGHT_GREEN, 2.0))
    return o


# ---------------------------------------------------------------------------------------------
# harbour and ships

def harbour_object(name, x, y, parts, heading=0.0):
    o = Obj(name, 'harbour', (x, y, 0.0), heading)
    for pname, colour, faces, roof in parts:
        o.part(pname, colour, 0).solid(faces, (lambda f, r=roof: r if is_roof(f) else None) if roof else None)
    return o


def build_harbour(world):
    x0, x1, y0, y1 = world.harbour['basin']
    ym = (y0 + y1) / 2
    quay = (0.50, 0.50, 0.48)
    west = box_faces(-10, 10, y0 - ym - 20, y1 - ym + 20, 0.0, 1.8)
    yield harbour_object('harbour_quay_west', x0 - 10, ym, [('quay', quay, west, None)])
    for name, yq in (('south', y0 - 10), ('north', y1 + 10)):
        side = box_faces(-(x1 - x0) / 2 - 10, (x1 - x0) / 2 + 10, -10, 10, 0.0, 1.8)
        yield harbour_object('harbour_quay_' + name, (x0 + x1) / 2 - 10, yq, [('quay', quay, side, None)])
    n = max(2, int((y1 - y0) // 170))
    for k in range(n):
        yc = y0 + (y1 - y0) * (k + 0.5) / n
        yield harbour_object('harbour_shed_%d' % (k + 1), x0 - 95, yc, [
            ('shed', (0.55, 0.52, 0.46), gabled_faces(-35, 35, -55, 55, 0.0, 9.0, 13.0), (0.38, 0.40, 0.42))])
        yield harbour_object('harbour_crane_%d' % (k + 1), x0 - 12, yc + 40, [
            ('boom', (0.85, 0.55, 0.10), box_faces(-4, 30, -1.2, 1.2, 30.0, 33.0), None),
            ('tower', (0.85, 0.55, 0.10), box_faces(-4, 4, -4, 4, 1.8, 30.0), None)])


SHIP_TYPES = {
    # length, beam, freeboard, superstructure (length, height), hull colour, cargo rows
    'cargo': (120.0, 18.0, 7.0, (16.0, 12.0), (0.12, 0.18, 0.30), 5),
    'tanker': (150.0, 22.0, 8.0, (14.0, 13.0), (0.35, 0.10, 0.08), 0),
    'ferry': (80.0, 16.0, 6.0, (50.0, 9.0), (0.85, 0.85, 0.85), 0),
    'tug': (25.0, 8.0, 3.0, (8.0, 4.0), (0.10, 0.10, 0.10), 0),
    'barge': (60.0, 10.0, 2.5, (6.0, 3.0), (0.25, 0.20, 0.15), 3),
}


def build_ship(world, k):
    kind, x, y, heading = world.ships[k]
    length, beam, board, (sl, sh), hull_c, rows = SHIP_TYPES[kind]
    rng = rng_for(world.seed, 400, k)
    o = Obj('ship_%d_%s' % (k, kind), 'ship', (x, y, 0.0), heading)
    hl, hb = length / 2, beam / 2
    plan = [(-hb, -hl), (hb, -hl), (hb, hl - 0.15 * length), (0.0, hl), (-hb, hl - 0.15 * length)]
    deck = board + WATER_Z
    for r in range(rows):
        yc = -hl + sl + 6 + r * (length - sl - 0.15 * length - 12) / max(1, rows)
        part = o.part('cargo_%d' % r, rng.choice(CONTAINERS), 0)
        part.solid(box_faces(-hb + 1.5, hb - 1.5, yc, yc + 12.0, deck, deck + 2.6 * rng.randint(1, 3)))
    o.part('funnel', (0.20, 0.20, 0.22), 0).solid(box_faces(-1.5, 1.5, -hl + sl * 0.3, -hl + sl * 0.3 + 3,
                                                            deck + sh, deck + sh + 4))
    o.part('superstructure', (0.88, 0.88, 0.85), 0).solid(box_faces(-hb + 1, hb - 1, -hl + 2, -hl + 2 + sl,
                                                                    deck, deck + sh))
    hull = prism_faces(plan, WATER_Z, deck)
    o.part('hull', hull_c, 30).solid(hull, lambda f: (0.40, 0.38, 0.35) if is_roof(f) else None)
    return o


# ---------------------------------------------------------------------------------------------
# observer path

def runway_ends(af, towards):
    """The runway's two ends, the one nearer `towards` first."""
    e1, e2 = af.to_world(0, -RUNWAY_HALF_L), af.to_world(0, RUNWAY_HALF_L)
    if math.hypot(e1[0] - towards[0], e1[1] - towards[1]) > math.hypot(e2[0] - towards[0], e2[1] - towards[1]):
        e1, e2 = e2, e1
    return e1, e2


def waypoints(world):
    """(x, y, height above ground, pitch): from beyond the port town over the harbour, up the
    river past the ships, over a forest, along the runway, over a second forest and the town."""
    f = world.f
    town, port, af = world.towns[0], world.towns[1], world.airfields[0]
    fa, fb = world.core(*CORE_FOREST_A[:2]), world.core(*CORE_FOREST_B[:2])
    b = world.harbour['basin']
    w = [(port.x - 2500 * f, port.y - 1500 * f, 250, -6), (port.x, port.y, 200, -7),
         ((b[0] + b[1]) / 2, (b[2] + b[3]) / 2, 110, -9)]
    y = world.harbour['y'] + 700 * max(0.5, f)
    while y < 0.0:
        w.append((river_x(world, y), y, 120, -8))
        y += 1000 * f
    w.append((fb[0], fb[1], 300, -6))
    e1, e2 = runway_ends(af, fb)
    dx, dy = (e2[0] - e1[0]) / (2 * RUNWAY_HALF_L), (e2[1] - e1[1]) / (2 * RUNWAY_HALF_L)
    w += [(e1[0] - dx * 1500 * f, e1[1] - dy * 1500 * f, 200, -6), (e1[0], e1[1], 150, -6), (e2[0], e2[1], 150, -6),
          (fa[0], fa[1], 300, -6), (town.x, town.y, 250, -7), (town.x - 2500 * f, town.y + 1500 * f, 280, -6)]
    m = 300.0
    return [(min(max(x, -world.half + m), world.half - m), min(max(y, -world.half + m), world.half - m), a, p)
            for x, y, a, p in w]


def chaikin(points, rounds):
    for _ in range(rounds):
        out = [points[0]]
        for p, q in zip(points, points[1:]):
            out.append(tuple(0.75 * a + 0.25 * b for a, b in zip(p, q)))
            out.append(tuple(0.25 * a + 0.75 * b for a, b in zip(p, q)))
        out.append(points[-1])
        points = out
    return points


def sample_path(points, count):
    """`count` points at equal arc length along a polyline of (x, y, agl, pitch)."""
    acc = [0.0]
    for p, q in zip(points, points[1:]):
        acc.append(acc[-1] + math.hypot(q[0] - p[0], q[1] - p[1]))
    out, seg = [], 0
    for k in range(count):
        s = acc[-1] * k / (count - 1)
        while seg < len(points) - 2 and acc[seg + 1] < s:
            seg += 1
        t = (s - acc[seg]) / max(1e-9, acc[seg + 1] - acc[seg])
        out.append(tuple(a + t * (b - a) for a, b in zip(points[seg], points[seg + 1])))
    return out, acc[-1]


def observer(world):
    """Keyframes every KEY_STEP frames: heading along the path, banked into turns, at least 110 m
    above every point of the ground under the interpolated path."""
    frames, length = sample_path(chaikin(waypoints(world), 4), FRAMES)
    keys = list(range(0, FRAMES, KEY_STEP))
    if keys[-1] != FRAMES - 1:
        keys.append(FRAMES - 1)
    heading = [heading_of(frames[min(k + 1, FRAMES - 1)][0] - frames[max(k - 1, 0)][0],
                          frames[min(k + 1, FRAMES - 1)][1] - frames[max(k - 1, 0)][1]) for k in range(FRAMES)]
    out = []
    for n, k in enumerate(keys):
        x, y, agl, pitch = frames[k]
        lo, hi = keys[max(0, n - 1)], keys[min(len(keys) - 1, n + 1)]
        floor = max(world.ground_z(*frames[m][:2]) for m in range(lo, hi + 1))
        z = max(world.ground_z(x, y) + agl, floor + 110.0)
        run = sum(math.hypot(frames[m + 1][0] - frames[m][0], frames[m + 1][1] - frames[m][1]) for m in range(lo, hi))
        curvature = math.radians((heading[hi] - heading[lo] + 540.0) % 360.0 - 180.0) / max(1.0, run)
        roll = max(-15.0, min(15.0, math.degrees(math.atan(250.0 * curvature))))
        out.append((k, (x, y, z), heading[k], pitch, roll))
    return out, length


def heights_above_ground(world, keys):
    """Smallest and largest height above the ground along the interpolated path (4 samples per frame)."""
    lo, hi = math.inf, -math.inf
    for (f0, p0, *_), (f1, p1, *_) in zip(keys, keys[1:]):
        n = 4 * (f1 - f0)
        for s in range(n + 1):
            t = s / n
            p = [a + t * (b - a) for a, b in zip(p0, p1)]
            h = p[2] - world.ground_z(p[0], p[1])
            lo, hi = min(lo, h), max(hi, h)
    return lo, hi


# ---------------------------------------------------------------------------------------------
# output

def num(v, digits=2):
    s = '%.*f' % (digits, v)
    if '.' in s:
        s = s.rstrip('0').rstrip('.')
    return '0' if s == '-0' else s


def vec(v, digits=2):
    return '[' + ','.join(num(c, digits) for c in v) + ']'


def colour(c):
    return vec(c, 3)


def part_json(p):
    head = '{'
    if p.name:
        head += '"name":"%s",' % p.name
    if p.colour is not None:
        head += '"colour":%s,' % colour(p.colour)
    if p.crease is not None:
        head += '"crease_angle":%s,' % num(p.crease)
    verts = ','.join('[%s,%s,%s]' % (num(x), num(y), num(z)) for x, y, z in p.verts)
    polys = ','.join('{"indices":[%s]%s}' % (','.join(map(str, idx)), ',"colour":' + colour(c) if c else '')
                     for idx, c in p.polys)
    return head + '"vertices":[' + verts + '],"polygons":[' + polys + ']}'


def object_json(o):
    s = '{"name":"%s","position":%s' % (o.name, vec(o.pos))
    if o.heading:
        s += ',"heading":%s' % num(o.heading, 3)
    if o.layer:
        s += ',"layer":%d' % o.layer
    if o.by_distance and len(o.parts) > 1:
        s += ',"subobject_order":"distance"'
    s += ',"subobjects":[' + ','.join(part_json(p) for p in o.parts) + ']'
    if o.lights:
        s += ',"light_points":[' + ','.join('{"position":%s,"diameter":%s,"colour":%s}' % (vec(p), num(d), colour(c))
                                            for p, c, d in o.lights) + ']'
    return s + '}'


def sun_direction():
    a, e = math.radians(SUN_AZ), math.radians(SUN_EL)
    return (math.sin(a) * math.cos(e), math.cos(a) * math.cos(e), math.sin(e))


def header_json(world, keys):
    chans = ',\n'.join('  {"name":"%s","yaw":%d,"pitch":0,"fov":40}' % (n, y)
                       for n, y in (('left', -40), ('centre', 0), ('right', 40)))
    kf = ',\n'.join('  {"frame":%d,"position":%s,"heading":%s,"pitch":%s,"roll":%s}'
                    % (k, vec(p), num(h), num(pi), num(r)) for k, p, h, pi, r in keys)
    return ('{\n"format":"cig-scene",\n"version":1,\n'
            '"name":"world to cull (scale %s, seed %d, %.0f x %.0f km)",\n' % ('%g' % world.scale, world.seed,
                                                                               world.side / 1000, world.side / 1000) +
            '"raster":512,\n"view":{"near":1.0,"range":%s,"light_point_min_diameter":6},\n' % num(FOG['end']) +
            '"channels":[\n%s\n],\n' % chans +
            '"lighting":{"sun_direction":%s,"sun_intensity":0.6,"ambient":0.35},\n' % vec(sun_direction(), 4) +
            '"fog":{"colour":%s,"start":%s,"end":%s},\n' % (colour(FOG['colour']), num(FOG['start']), num(FOG['end'])) +
            '"background":%s,\n' % colour(BACKGROUND) +
            '"observer":{"keyframes":[\n%s\n]},\n"objects":[\n' % kf)


class Stats:
    def __init__(self):
        self.kinds = {}

    def add(self, o):
        row = self.kinds.setdefault(o.kind, [0, 0, 0, 0, 0, 0])
        row[0] += 1
        row[1] += len(o.parts)
        row[2] += sum(len(p.polys) for p in o.parts)
        row[3] += sum(len(idx) - 2 for p in o.parts for idx, _ in p.polys)
        row[4] += sum(len(p.verts) for p in o.parts)
        row[5] += len(o.lights)

    def total(self):
        return [sum(r[k] for r in self.kinds.values()) for k in range(6)]


def all_objects(world):
    for tj in range(world.tiles):
        for ti in range(world.tiles):
            yield build_tile(world, ti, tj)
    for af in world.airfields:
        yield from build_airfield(world, af)
    for town in world.towns:
        yield from build_town(world, town)
    for k in range(len(world.farms)):
        yield build_farm(world, k)
    for k in range(len(world.stands)):
        o = build_stand(world, k)
        if o:
            yield o
    yield from build_harbour(world)
    for k in range(len(world.ships)):
        yield build_ship(world, k)


def write_world(world, keys, out):
    stats = Stats()
    out.write(header_json(world, keys))
    first = True
    for o in all_objects(world):
        if not o.parts and not o.lights:
            continue
        out.write(('' if first else ',\n') + object_json(o))
        first = False
        stats.add(o)
    out.write('\n]\n}\n')
    return stats


# ---------------------------------------------------------------------------------------------
# command line

def parse_args(argv):
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0],
                                 epilog='Example: python3 tools/make_world.py --out /tmp/world.json --print-stats')
    ap.add_argument('--out', required=True, help='scene file to write (atomically)')
    ap.add_argument('--scale', type=float, default=1.0,
                    help='content multiplier in (0, 100] (default 1: ~40 x 40 km, >= 200 k triangles)')
    ap.add_argument('--seed', type=int, default=1, help='random seed (default 1)')
    ap.add_argument('--print-stats', action='store_true',
                    help='print objects, subobjects, polygons and triangles (per kind and in total)')
    args = ap.parse_args(argv)
    if not (math.isfinite(args.scale) and 0 < args.scale <= 100):
        ap.error('--scale must be greater than 0 and at most 100, got %s' % args.scale)
    if args.seed < 0 or args.seed >= 2 ** 63:
        ap.error('--seed must be in [0, 2^63), got %d' % args.seed)
    check_writable(ap, args.out)
    return args


def check_writable(ap, path):
    folder = os.path.dirname(os.path.abspath(path))
    if os.path.isdir(path):
        ap.error('--out %s is a directory' % path)
    if not os.path.isdir(folder):
        ap.error('--out %s: folder %s does not exist' % (path, folder))
    if not os.access(folder, os.W_OK | os.X_OK):
        ap.error('--out %s: folder %s is not writable' % (path, folder))
    if os.path.exists(path) and not os.path.isfile(path):
        ap.error('--out %s exists and is not a regular file' % path)
    if os.path.exists(path) and not os.access(path, os.W_OK):
        ap.error('--out %s is not writable' % path)


def write_atomically(path, write):
    """Write through a temporary file in the same folder and rename it over `path`."""
    folder = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(prefix='.make_world.', suffix='.tmp', dir=folder)
    try:
        with os.fdopen(fd, 'w', encoding='ascii', newline='\n', buffering=1 << 20) as out:
            result = write(out)
        mask = os.umask(0)
        os.umask(mask)
        os.chmod(tmp, 0o666 & ~mask)
        os.replace(tmp, path)
        return result
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def print_stats(world, stats, keys, length, path, seconds):
    lo, hi = heights_above_ground(world, keys)
    print('world: %.0f x %.0f km, scale %s, seed %d; %d tiles, %d towns, %d airfields, %d farms, %d forest stands, '
          '%d ships' % (world.side / 1000, world.side / 1000, '%g' % world.scale, world.seed, world.tiles ** 2,
                        len(world.towns), len(world.airfields), len(world.farms), len(world.stands), len(world.ships)))
    print('%-10s %9s %11s %10s %10s %10s %7s' % ('kind', 'objects', 'subobjects', 'polygons', 'triangles',
                                                 'vertices', 'lights'))
    for kind in sorted(stats.kinds):
        print('%-10s %9d %11d %10d %10d %10d %7d' % ((kind,) + tuple(stats.kinds[kind])))
    print('%-10s %9d %11d %10d %10d %10d %7d' % (('total',) + tuple(stats.total())))
    print('objects %d\nsubobjects %d\npolygons %d\ntriangles %d' % tuple(stats.total()[:4]))
    print('path: %d frames, %.1f km, %.0f to %.0f m above the ground' % (FRAMES, length / 1000, lo, hi))
    print('file: %s, %d bytes (%.1f MB), written in %.1f s' % (path, os.path.getsize(path),
                                                             os.path.getsize(path) / 1e6, seconds))


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    start = time.time()
    world = plan_world(args.scale, args.seed)
    keys, length = observer(world)
    try:
        stats = write_atomically(args.out, lambda out: write_world(world, keys, out))
    except OSError as e:
        sys.stderr.write('make_world.py: error: cannot write %s: %s\n' % (args.out, e.strerror or e))
        return 2
    if os.path.getsize(args.out) > MAX_SCENE_BYTES:
        sys.stderr.write('make_world.py: warning: %s is larger than the 256 MiB cig reads\n' % args.out)
    if args.print_stats:
        print_stats(world, stats, keys, length, args.out, time.time() - start)
    return 0


if __name__ == '__main__':
    sys.exit(main())
