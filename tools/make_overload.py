#!/usr/bin/env python3
"""Writes scenes/stress/overload.polys.json: a polygon list that overloads the segment memory.

    python3 tools/make_overload.py [OUTPUT]      (default scenes/stress/overload.polys.json)

The segment processor (SPEC D) stores one segment per raster line a polygon crosses (and one per
sample row a light point covers) in a segment memory of 2 x 48K words: even lines in one bank,
odd lines in the other. This scene holds more than 96K segments, so overload protection must
drop polygons: every polygon gets an area code (eq. 6: 1 the largest .. 15 the smallest, 0 when
protected), and the threshold T is the largest code for which the segments of all codes <= T fit
both banks. The scene is built so that

  * polygons of every area code 1..15 are present, from full-height strips to sub-pixel
    triangles, with many shapes (strips, slivers, random convex polygons of 3..9 vertices);
  * a set of polygons is protected (code 0), large ones and small ones (whose size alone would
    give codes 11..15): they must survive the overload;
  * light points (never dropped) hold a few thousand segments, and the code-10 bucket ends just
    past the capacity: the threshold is T = 9 when the lights' segments are counted, and a
    threshold that ignored them would keep code 10 and overflow a bank;
  * the frame memory (2 x 16K words: a header and one word per edge) is not overloaded, so the
    only loss is the overload protection's.

Deterministic: a fixed seed and integer arithmetic only (no floating-point library calls), so
every Python 3 gives the same file. Positions are written with 5 decimals, which never lie on a
rounding tie of eq. 1 (X = 2048 Xs + 2047): 2048 * k / 10^5 has no fractional part 1/2. The
counts below mirror the segment processor's rules (scenes/README.md, hls/segment/README.md) for
the summary printed to stderr; verif/stress/test_overload.cpp recounts them independently.
"""

import math
import os
import sys

RASTER = 512                  # N: 512 x 512, 4 x 4 samples per pixel
ROWS = 4 * RASTER             # sample rows
BANK = 48 * 1024              # segment memory words per field (even / odd lines)
FRAME_WORDS = 16 * 1024       # frame memory words per bank
SCALE = 100000                # coordinates are integers in units of 1e-5 of Xs, Ys
TARGET_THRESHOLD = 9          # the bucket that ends the kept codes
BULK_MARGIN = 1200            # room left per field after codes <= 9, filled by code 10
SMALL_COUNTS = {11: 250, 12: 220, 13: 180, 14: 150, 15: 150}  # polygons beyond code 10
PROTECTED_LARGE = 6
PROTECTED_SMALL = 40
LIGHTS = 1200


class Rng:
    """splitmix64: a tiny deterministic generator (integers only)."""

    def __init__(self, seed):
        self.state = seed & 0xFFFFFFFFFFFFFFFF

    def next(self):
        self.state = (self.state + 0x9E3779B97F4A7C15) & 0xFFFFFFFFFFFFFFFF
        z = self.state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & 0xFFFFFFFFFFFFFFFF
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & 0xFFFFFFFFFFFFFFFF
        return z ^ (z >> 31)

    def below(self, n):
        return self.next() % n

    def between(self, lo, hi):
        return lo + self.below(hi - lo + 1)


# ---- The segment processor's counting rules (for the summary and the design) -------------------

def grid(m):
    """Eq. 1 on Xs = m / SCALE: round(2048 Xs + 2047), clamped to 0..4095 (no ties occur)."""
    num = 2048 * m + 2047 * SCALE
    return min(max((2 * num + SCALE) // (2 * SCALE), 0), 4095)


def row_half(k):
    """Y of sample row k in half grid units (records.hpp: u/2 * k + u/4 - 2, u = 4096 / N)."""
    u = 4096 // RASTER
    return u * k // 2 + u // 4 - 2


def first_row_at_or_after(y):
    """First sample row with Y_k >= y (y in grid units), unclamped."""
    u = 4096 // RASTER
    spacing, offset = u // 2, u // 4 - 2
    return -((offset - 2 * y) // spacing)  # ceil((2y - offset) / spacing)


def twice_area(pts):
    return abs(sum(pts[k][0] * pts[(k + 1) % len(pts)][1] - pts[(k + 1) % len(pts)][0] * pts[k][1]
                   for k in range(len(pts))))


def area_code(twice):
    """clamp(20 - floor(log2(area)), 1, 15), area = twice / 2 (hls/segment/README.md)."""
    return min(max(21 - (twice.bit_length() - 1), 1), 15)


def polygon_counts(poly):
    """(valid, code, segments even, segments odd, frame-memory words) of a polygon."""
    pts = [(grid(x), grid(y)) for x, y in poly["xy"]]
    twice = twice_area(pts)
    code = 0 if poly["protected"] else area_code(max(twice, 1))
    ys = [p[1] for p in pts]
    first = max(first_row_at_or_after(min(ys)), 0)
    last = min(first_row_at_or_after(max(ys)) - 1, ROWS - 1)
    if twice == 0 or first > last:
        return False, code, 0, 0, 0
    lines = [line for line in range(first // 4, last // 4 + 1)]
    even = sum(1 for line in lines if line % 2 == 0)
    edges = 0
    for k in range(len(pts)):
        (xa, ya), (xb, yb) = pts[k], pts[(k + 1) % len(pts)]
        y0, y1 = min(ya, yb), max(ya, yb)
        if y0 != y1 and max(first_row_at_or_after(y0), 0) <= min(first_row_at_or_after(y1) - 1, ROWS - 1):
            edges += 1
    return True, code, even, len(lines) - even, 1 + edges


def light_counts(light):
    """Segments (even, odd) of a light point: one per sample row within D/2 of its centre."""
    cy2 = 2 * grid(light["xy"][1])
    d = light["d"]
    even = odd = 0
    for k in range(max(first_row_at_or_after(0), 0), ROWS):
        if abs(row_half(k) - cy2) <= d:
            if (k // 4) % 2 == 0:
                even += 1
            else:
                odd += 1
    return even, odd


# ---- Shapes (integer coordinates in units of 1e-5 of Xs, Ys) ------------------------------------

def cross(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def strict_hull(points):
    """Strictly convex hull (collinear points dropped), counter-clockwise."""
    pts = sorted(set(points))
    if len(pts) < 3:
        return pts
    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def micro_from_grid(g):
    """Xs (in units of 1e-5) of grid position g / 2^20 (g a 2^20-scaled grid coordinate)."""
    num = (g - 2047 * (1 << 20)) * SCALE
    den = 2048 * (1 << 20)
    return (2 * num + den) // (2 * den)


def random_convex(rng, code, max_vertices=9):
    """A convex polygon whose twice-area (grid units^2) lies in code's octave, or None."""
    target = (1 << (21 - code)) + rng.below(1 << (21 - code))    # twice-area in [2^(21-c), 2^(22-c))
    a, b = rng.between(-1024, 1024), rng.between(-1024, 1024)
    c, d = rng.between(-1024, 1024), rng.between(-1024, 1024)
    if rng.below(4) == 0:  # a sliver: second column short and nearly perpendicular
        s = rng.between(1, 40)
        b, d = -c * s // 1024 + rng.between(-2, 2), a * s // 1024 + rng.between(-2, 2)
    pts = []
    for _ in range(rng.between(3, 24)):
        while True:
            u, v = rng.between(-1024, 1024), rng.between(-1024, 1024)
            if u * u + v * v <= 1024 * 1024:
                break
        pts.append((a * u + b * v, c * u + d * v))
    hull = strict_hull(pts)
    if len(hull) < 3:
        return None
    if len(hull) > max_vertices:
        keep = rng.between(3, max_vertices)
        hull = [hull[k * len(hull) // keep] for k in range(keep)]
    area0 = twice_area(hull)
    if area0 == 0:
        return None
    # Scale s (2^20-scaled grid units per shape unit) with s^2 * area0 = target.
    s = math.isqrt((target << 40) // area0)
    xs = [p[0] * s for p in hull]
    ys = [p[1] * s for p in hull]
    w, h = max(xs) - min(xs), max(ys) - min(ys)
    span = 4095 << 20
    if w >= span or h >= span:
        return None
    cx = rng.below(span - w + 1) - min(xs)
    cy = rng.below(span - h + 1) - min(ys)
    xy = [(micro_from_grid(x + cx), micro_from_grid(y + cy)) for x, y in zip(xs, ys)]
    hull = strict_hull(xy)  # rounding to 1e-5 may make a vertex collinear: keep it strictly convex
    return hull if len(hull) >= 3 else None


def strip(rng):
    """A tall strip (a trapezoid with horizontal top and bottom): area code 1, many lines."""
    top = rng.between(-SCALE, -SCALE // 2)
    bottom = rng.between(SCALE // 2, SCALE)
    width_top = rng.between(SCALE // 7, SCALE // 4)
    width_bottom = rng.between(SCALE // 7, SCALE // 4)
    x_top = rng.between(-SCALE, SCALE - width_top)
    x_bottom = min(max(x_top + rng.between(-SCALE // 4, SCALE // 4), -SCALE), SCALE - width_bottom)
    return [(x_top, top), (x_top + width_top, top), (x_bottom + width_bottom, bottom), (x_bottom, bottom)]


def make_polygon(rng, code, protected=False):
    """A polygon of the given area code (strips for code 1), or None after too many tries."""
    for _ in range(200):
        xy = strip(rng) if code == 1 else random_convex(rng, code)
        if xy is None:
            continue
        poly = {"xy": xy, "protected": protected}
        valid, got, _, _, _ = polygon_counts(dict(poly, protected=False))
        if valid and got == code:
            return poly
    raise SystemExit("make_overload: could not build a polygon of area code %d" % code)


def decorate(rng, poly):
    """Depth, Gouraud intensities and colour (not used by the overload decision)."""
    poly["z"] = rng.between(20, 20000)
    poly["i"] = [rng.between(30, 100) for _ in poly["xy"]]
    poly["colour"] = [rng.between(5, 95) for _ in range(3)]


# ---- The scene ----------------------------------------------------------------------------------

def build():
    rng = Rng(0x5E6E0AD)
    lights = []
    for _ in range(LIGHTS):
        lights.append({"xy": (rng.between(-98000, 98000), rng.between(-98000, 98000)),
                       "d": rng.between(2, 7), "z": rng.between(50, 5000),
                       "colour": [100, rng.between(70, 100), rng.between(30, 90)],
                       "intensity": rng.between(60, 100)})
    light_segments = [0, 0]
    for light in lights:
        e, o = light_counts(light)
        light_segments[0] += e
        light_segments[1] += o

    polys = []
    counts = [[0] * 16 for _ in range(2)]  # [field][code]

    def add(poly):
        valid, code, even, odd, _ = polygon_counts(poly)
        if valid:
            counts[0][code] += even
            counts[1][code] += odd
        polys.append(poly)

    def kept(field, threshold):
        return sum(counts[field][:threshold + 1]) + light_segments[field]

    # Protected polygons: large strips and small ones that would otherwise be dropped first.
    for _ in range(PROTECTED_LARGE):
        add(make_polygon(rng, 1, protected=True))
    for k in range(PROTECTED_SMALL):
        add(make_polygon(rng, 11 + k % 5, protected=True))

    # Codes 1..9 up to BULK_MARGIN below the capacity: strips carry most of the segments.
    mix = [1, 2, 1, 3, 4, 1, 5, 6, 7, 1, 8, 9, 9, 8, 7, 6]
    k = 0
    while True:
        poly = make_polygon(rng, mix[k % len(mix)])
        k += 1
        valid, code, even, odd, _ = polygon_counts(poly)
        if max(kept(0, TARGET_THRESHOLD) + even, kept(1, TARGET_THRESHOLD) + odd) > BANK - BULK_MARGIN:
            break
        add(poly)

    # Code 10 until it no longer fits with the lights: the threshold becomes 9.
    while kept(0, 10) <= BANK and kept(1, 10) <= BANK:
        add(make_polygon(rng, 10))
    if max(sum(counts[f][:11]) for f in range(2)) > BANK:
        raise SystemExit("make_overload: code 10 alone overflows; the lights would not matter")

    for code, count in sorted(SMALL_COUNTS.items()):
        for _ in range(count):
            add(make_polygon(rng, code))

    # Priority order: shuffled, so protected, large and small polygons interleave.
    for i in range(len(polys) - 1, 0, -1):
        j = rng.below(i + 1)
        polys[i], polys[j] = polys[j], polys[i]
    for poly in polys:
        decorate(rng, poly)
    for light in lights:
        light["priority"] = rng.below(len(polys) + 1)
    return polys, lights, counts, light_segments


def fmt_fixed(value, decimals):
    """An integer in units of 10^-decimals as a JSON number (exact decimal, no float)."""
    sign = "-" if value < 0 else ""
    value = abs(value)
    whole, frac = divmod(value, 10 ** decimals)
    text = "%s%d.%0*d" % (sign, whole, decimals, frac)
    return text.rstrip("0").rstrip(".") if "." in text else text


def write(path, polys, lights):
    out = ['{"format": "cig-polys", "version": 1, "raster": %d,' % RASTER,
           ' "background": [0.35, 0.42, 0.55],', ' "polygons": [']
    for n, poly in enumerate(polys):
        vertices = ",".join("[%s,%s,%d,%s]" % (fmt_fixed(x, 5), fmt_fixed(y, 5), poly["z"], fmt_fixed(i, 2))
                            for (x, y), i in zip(poly["xy"], poly["i"]))
        colour = ",".join(fmt_fixed(c, 2) for c in poly["colour"])
        flag = ',"protected":true' if poly["protected"] else ""
        out.append('  {"colour":[%s]%s,"vertices":[%s]}%s' % (colour, flag, vertices,
                                                             "," if n + 1 < len(polys) else ""))
    out.append(' ],')
    out.append(' "light_points": [')
    for n, light in enumerate(lights):
        out.append('  {"centre":[%s,%s,%d],"diameter":%s,"colour":[%s],"intensity":%s,"priority":%d}%s' % (
            fmt_fixed(light["xy"][0], 5), fmt_fixed(light["xy"][1], 5), light["z"],
            repr(light["d"] / 2048), ",".join(fmt_fixed(c, 2) for c in light["colour"]),
            fmt_fixed(light["intensity"], 2), light["priority"], "," if n + 1 < len(lights) else ""))
    out.append(' ]')
    out.append('}')
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="ascii") as f:
        f.write("\n".join(out) + "\n")
    os.replace(tmp, path)


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "scenes", "stress", "overload.polys.json")
    polys, lights, counts, light_segments = build()
    words = 0
    for poly in polys:
        valid, _, _, _, w = polygon_counts(poly)
        words += w if valid else 0
    if words > FRAME_WORDS:
        raise SystemExit("make_overload: %d frame-memory words exceed %d" % (words, FRAME_WORDS))

    def fits(threshold, with_lights):
        return all(sum(counts[f][:threshold + 1]) + (light_segments[f] if with_lights else 0) <= BANK
                   for f in range(2))

    threshold = max([t for t in range(16) if fits(t, True)] or [0])
    threshold_without_lights = max([t for t in range(16) if fits(t, False)] or [0])
    total = sum(map(sum, counts)) + sum(light_segments)
    dirname = os.path.dirname(path)
    if dirname:
        os.makedirs(dirname, exist_ok=True)
    write(path, polys, lights)
    print("make_overload: wrote %s: %d polygons (%d protected), %d light points, %d frame-memory words"
          % (path, len(polys), sum(p["protected"] for p in polys), len(lights), words), file=sys.stderr)
    print("  segments %d (> 2 x %d): light %d + %d (even + odd)" % (total, BANK, *light_segments), file=sys.stderr)
    for code in range(16):
        print("  code %2d: %6d + %6d" % (code, counts[0][code], counts[1][code]), file=sys.stderr)
    print("  threshold %d (%d if the lights were not counted)" % (threshold, threshold_without_lights),
          file=sys.stderr)


if __name__ == "__main__":
    main()
