// Helpers of the segment-kernel tests (test_segment_*.cpp): exact references (128-bit rationals),
// the e8m7 value of a code, seeded random convex polygons on the integer grid and their kernel
// inputs (fixed: FormattedPrimitive; twin: the same integers as doubles), and the exact sample
// coverage of a polygon (edge functions with the top-left rule). Everything here is independent
// of the kernels except the record types it fills. Randomness uses only the raw mt19937_64 stream
// (no std distributions, no libm), so generated inputs are the same on every platform.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "hls/segment/records.hpp"
#include "hls/segment/segment_arith.hpp"
#include "segment/double_arith.hpp"

namespace cig::hls::segtest {

using i128 = __int128;
using Rng = std::mt19937_64;
using Twin = cig::DoubleSegmentArith;

inline std::int64_t below(Rng& rng, std::int64_t n) { return std::int64_t(rng() % std::uint64_t(n)); }
inline std::int64_t between(Rng& rng, std::int64_t lo, std::int64_t hi) { return lo + below(rng, hi - lo + 1); }

// ---- Exact arithmetic ----------------------------------------------------------------------------

inline i128 floor_div(i128 n, i128 d) {  // d > 0
  i128 q = n / d;
  if ((n % d) != 0 && n < 0) q -= 1;
  return q;
}
inline i128 ceil_div(i128 n, i128 d) { return -floor_div(-n, d); }  // d > 0
// n / d rounded half up (d > 0): floor(n/d + 1/2).
inline i128 round_half_up(i128 n, i128 d) { return floor_div(2 * n + d, 2 * d); }
inline i128 abs128(i128 v) { return v < 0 ? -v : v; }
// v * 2^k without shifting a negative value (k >= 0).
inline i128 mul2k(i128 v, int k) { return v * (i128(1) << k); }

// The exact value of a fixed-point number (exact in binary64 for widths up to 53 bits).
template <class T>
double value_of(const T& x) {
  return std::ldexp(double(x.raw().value()), -T::frac_bits);
}
template <class T>
std::int64_t raw_of(const T& x) {
  return std::int64_t(x.raw().value());
}

// ---- e8m7 ----------------------------------------------------------------------------------------

inline ZFloat zcode(int code) {
  ZFloat z;
  z.bits = UInt<15>(code);
  return z;
}
inline int code_of(const ZFloat& z) { return int(z.bits.value()); }
// The value of an e8m7 code: 2^(E - 127) * (128 + m) / 128, exact in binary64.
inline double zvalue(int code) { return std::ldexp(double(128 + (code & 127)), (code >> 7) - 127 - 7); }

// The e8m7 code nearest (ties to even) to the non-negative rational p/q * 2^base_exp, saturating:
// values below 2^-127 (and zero) give code 0, values at or above the rounding limit of the largest
// code give 0x7FFF. p >= 0, q > 0, p and q below 2^120.
inline int rne_code(i128 p, i128 q, int base_exp) {
  if (p <= 0) return 0;
  // k = floor(log2(p/q)): 2^k <= p/q < 2^(k+1).
  int k = 0;
  {
    int lp = 0, lq = 0;
    for (i128 t = p; t > 1; t >>= 1) ++lp;
    for (i128 t = q; t > 1; t >>= 1) ++lq;
    k = lp - lq;                // within one of the truth
    auto ge_pow = [&](int e) {  // p/q >= 2^e ?
      return e >= 0 ? p >= (q << e) : (p << -e) >= q;
    };
    while (!ge_pow(k)) --k;
    while (ge_pow(k + 1)) ++k;
  }
  // Significand s = p/q * 2^(7 - k) in [128, 256), rounded to nearest even.
  const int sh = 7 - k;
  i128 num = p, den = q;
  if (sh >= 0) num <<= sh;
  else den <<= -sh;
  i128 s = num / den;
  const i128 r2 = 2 * (num - s * den);
  if (r2 > den || (r2 == den && (s & 1))) ++s;
  int e = k + base_exp + 127;
  if (s == 256) {
    s = 128;
    ++e;
  }
  if (e < 0) return 0;
  if (e > 255) return 0x7FFF;
  return e * 128 + int(s - 128);
}

// Checks one result r of a + (b - a) * num / den (den > 0) against the exact rational value v.
//
// Derivation of the admissible codes. zfloat_lerp aligns both 8-bit significands to the larger
// exponent E with 12 guard bits; one unit there is U = 2^(E - 127 - 7 - 12). The operand with the
// smaller exponent loses the bits shifted out (truncation, delta in [0, U); none when the exponent
// difference d <= 12; the whole operand when d >= 20). The interpolation is exact except one
// division (or, for the ratio form, one product) rounded half up: +-U/2. So the value the kernel
// rounds is x = v + err with |err| <= E = delta_a * |1 - t| + delta_b * |t| + U/2, t = num/den; the
// final rounding to e8m7 is round-to-nearest-even with saturation (below 2^-127 -> code 0, beyond
// the largest code -> 0x7FFF). Rounding is monotone, so r must lie between the correctly rounded
// codes of v - E and v + E; when err is zero (no truncation, exact quotient), r must be exactly the
// correctly rounded code of v (ties to even).
struct LerpVerdict {
  bool ok = false;
  bool must_be_exact = false;
  int rne = 0, lo = 0, hi = 0;
};
inline LerpVerdict judge_lerp(int ca, int cb, std::int64_t num, std::int64_t den, int r) {
  const int ea = ca >> 7, eb = cb >> 7;
  const i128 siga = 128 + (ca & 127), sigb = 128 + (cb & 127);
  const int emax = std::max(ea, eb), d = std::abs(ea - eb), dd = std::min(d, 60);
  // Unit 2^base with base = emax - 147 - dd: U = 2^(dd + 1) units. Beyond d = 60 the smaller
  // operand (< 2^-40 U) is replaced by 0, which its delta bound (U) covers.
  const int base = emax - 147 - dd;
  const i128 U = i128(1) << (dd + 1);
  auto scaled = [&](i128 sig, int e) -> i128 {
    if (emax - e > 60) return 0;
    return sig << (13 + dd - (emax - e));
  };
  const i128 A = scaled(siga, ea), B = scaled(sigb, eb);
  const i128 da = (ea < emax && d > 12) ? U : 0, db = (eb < emax && d > 12) ? U : 0;
  const i128 n = num, q = den;
  const i128 v2 = 2 * (A * q + (B - A) * n);                            // 2 * den * v
  const i128 e2 = 2 * da * abs128(q - n) + 2 * db * abs128(n) + U * q;  // 2 * den * E
  LerpVerdict out;
  out.rne = rne_code(v2, 2 * q, base);
  out.lo = rne_code(v2 - e2, 2 * q, base);
  out.hi = rne_code(v2 + e2, 2 * q, base);
  out.must_be_exact = da == 0 && db == 0 && ((B - A) * n) % (q * U) == 0;
  out.ok = out.must_be_exact ? r == out.rne : (out.lo <= r && r <= out.hi);
  return out;
}

// ---- Random convex polygons on the grid ------------------------------------------------------------

struct IntPolygon {
  int n = 0;
  int x[kMaxVertices] = {}, y[kMaxVertices] = {};
  int i[kMaxVertices] = {};  // intensity 0..255
  int z[kMaxVertices] = {};  // e8m7 codes
  int colour[3] = {0, 0, 0};
  bool opaque = true, protect = false;
  int id = 0;
};

// Twice the signed area in grid units^2, x_j y_{j+1} - x_{j+1} y_j summed (math orientation).
inline std::int64_t shoelace2(const IntPolygon& p) {
  std::int64_t s = 0;
  for (int k = 0; k < p.n; ++k) {
    const int k1 = (k + 1) % p.n;
    s += std::int64_t(p.x[k]) * p.y[k1] - std::int64_t(p.x[k1]) * p.y[k];
  }
  return s;
}

namespace detail_gen {
inline std::int64_t cross(std::int64_t ox, std::int64_t oy, std::int64_t ax, std::int64_t ay, std::int64_t bx,
                          std::int64_t by) {
  return (ax - ox) * (by - oy) - (ay - oy) * (bx - ox);
}
// Strict convex hull (Andrew's monotone chain, collinear points dropped), counter-clockwise.
inline std::vector<std::pair<int, int>> hull(std::vector<std::pair<int, int>> pts) {
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return pts;
  std::vector<std::pair<int, int>> h(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 &&
           cross(h[k - 2].first, h[k - 2].second, h[k - 1].first, h[k - 1].second, pts[i].first, pts[i].second) <= 0)
      --k;
    h[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(h[k - 2].first, h[k - 2].second, h[k - 1].first, h[k - 1].second, pts[i - 1].first,
                           pts[i - 1].second) <= 0)
      --k;
    h[k++] = pts[i - 1];
  }
  h.resize(k - 1);
  return h;
}
}  // namespace detail_gen

enum class Shape { kLarge, kMedium, kSmall, kSliver, kBorder, kDegenerate, kCollinearVertex, kAny };

// A convex polygon: random points in an affine image of a disc, clamped to the grid, their strict
// hull (at most 16 vertices: an evenly spaced subset of a larger hull, still strictly convex),
// random orientation and start vertex. kDegenerate gives collinear vertices (zero area);
// kCollinearVertex inserts a vertex in the middle of an edge. Attributes: I 0..255 (0 and 255 in a
// quarter of the vertices, where extrapolation saturates), Z codes around a
// random exponent (neighbouring binades), colour, flags.
inline IntPolygon random_polygon(Rng& rng, Shape shape, int id) {
  if (shape == Shape::kAny) {
    const int r = int(below(rng, 100));
    shape = r < 30   ? Shape::kLarge
            : r < 55 ? Shape::kMedium
            : r < 70 ? Shape::kSmall
            : r < 82 ? Shape::kSliver
            : r < 92 ? Shape::kBorder
            : r < 95 ? Shape::kDegenerate
                     : Shape::kCollinearVertex;
  }
  IntPolygon p;
  p.id = id;
  for (int c = 0; c < 3; ++c) p.colour[c] = int(below(rng, 256));
  p.opaque = below(rng, 4) != 0;
  p.protect = below(rng, 8) == 0;
  std::vector<std::pair<int, int>> h;
  for (int attempt = 0; attempt < 100 && h.size() < 3; ++attempt) {
    std::int64_t extent = 0, cx = between(rng, 0, 4095), cy = between(rng, 0, 4095);
    switch (shape) {
      case Shape::kLarge:
        extent = between(rng, 300, 2600);
        break;
      case Shape::kMedium:
        extent = between(rng, 30, 300);
        break;
      case Shape::kSmall:
        extent = between(rng, 2, 30);
        break;
      case Shape::kSliver:
        extent = between(rng, 100, 3000);
        break;
      case Shape::kBorder:
        extent = between(rng, 50, 1500);
        if (below(rng, 2)) cx = below(rng, 2) ? between(rng, -400, 60) : between(rng, 4035, 4500);
        else cy = below(rng, 2) ? between(rng, -400, 60) : between(rng, 4035, 4500);
        break;
      default:
        extent = between(rng, 20, 1500);
        break;
    }
    // Columns of the affine map (units of extent / 1024 per disc unit).
    std::int64_t a = between(rng, -1024, 1024), c = between(rng, -1024, 1024);
    std::int64_t b = between(rng, -1024, 1024), d = between(rng, -1024, 1024);
    if (shape == Shape::kSliver) {  // second column short and roughly perpendicular
      const std::int64_t s = between(rng, 1, 24);
      b = -c * s / 1024 + between(rng, -2, 2);
      d = a * s / 1024 + between(rng, -2, 2);
    }
    const int m = int(between(rng, 3, 32));
    std::vector<std::pair<int, int>> pts;
    for (int k = 0; k < m; ++k) {
      std::int64_t u = 0, v = 0;
      do {
        u = between(rng, -1024, 1024);
        v = between(rng, -1024, 1024);
      } while (u * u + v * v > 1024 * 1024);
      std::int64_t x = cx + floor_div(i128(extent) * (a * u + b * v), i128(1024) * 1024);
      std::int64_t y = cy + floor_div(i128(extent) * (c * u + d * v), i128(1024) * 1024);
      x = std::clamp<std::int64_t>(x, 0, 4095);
      y = std::clamp<std::int64_t>(y, 0, 4095);
      pts.push_back({int(x), int(y)});
    }
    h = detail_gen::hull(pts);
  }
  if (h.size() < 3) {  // a fallback triangle
    h = {{100, 100}, {200, 100}, {150, 300}};
  }
  if (h.size() > std::size_t(kMaxVertices)) {
    std::vector<std::pair<int, int>> sub;
    const int keep = int(between(rng, 3, kMaxVertices));
    for (int k = 0; k < keep; ++k) sub.push_back(h[std::size_t(k) * h.size() / std::size_t(keep)]);
    h = sub;
  }
  if (shape == Shape::kDegenerate) {  // three collinear points (possibly repeated)
    const auto p0 = h[0], p1 = h[1];
    const int t = int(between(rng, 0, 4));
    h = {p0, {p0.first + (p1.first - p0.first) * t / 4, p0.second + (p1.second - p0.second) * t / 4}, p1};
  } else if (shape == Shape::kCollinearVertex && h.size() < std::size_t(kMaxVertices)) {
    const std::size_t e = std::size_t(below(rng, std::int64_t(h.size())));
    const auto p0 = h[e], p1 = h[(e + 1) % h.size()];
    if ((p0.first + p1.first) % 2 == 0 && (p0.second + p1.second) % 2 == 0)
      h.insert(h.begin() + std::ptrdiff_t(e) + 1, {(p0.first + p1.first) / 2, (p0.second + p1.second) / 2});
  }
  if (below(rng, 2)) std::reverse(h.begin(), h.end());
  std::rotate(h.begin(), h.begin() + std::ptrdiff_t(below(rng, std::int64_t(h.size()))), h.end());
  p.n = int(h.size());
  const int e0 = int(between(rng, 118, 140));
  for (int k = 0; k < p.n; ++k) {
    p.x[k] = h[std::size_t(k)].first;
    p.y[k] = h[std::size_t(k)].second;
    p.i[k] = below(rng, 4) == 0 ? (below(rng, 2) ? 255 : 0) : int(below(rng, 256));  // extremes often
    p.z[k] = int(std::clamp<std::int64_t>(e0 + between(rng, -2, 2), 0, 255) * 128 + below(rng, 128));
  }
  return p;
}

// The formatter's output for the polygon (what the fixed kernels read).
inline FormattedPrimitive fixed_input(const IntPolygon& p) {
  FormattedPrimitive f;
  f.is_light = false;
  f.n = UInt<5>(p.n);
  for (int k = 0; k < p.n; ++k) {
    f.v[k].x = UInt<12>(p.x[k]);
    f.v[k].y = UInt<12>(p.y[k]);
    f.v[k].i = UInt<8>(p.i[k]);
    f.v[k].z = zcode(p.z[k]);
  }
  for (int c = 0; c < 3; ++c) f.colour[c] = UInt<8>(p.colour[c]);
  f.opaque = p.opaque;
  f.protect = p.protect;
  f.id = UInt<16>(p.id);
  return f;
}

// The twin's input: the same integers (and the exact value of each depth code) as doubles.
inline FormattedPrimitiveT<Twin> twin_input(const IntPolygon& p) {
  FormattedPrimitiveT<Twin> f;
  f.is_light = false;
  f.n = UInt<5>(p.n);
  for (int k = 0; k < p.n; ++k) f.v[k] = {double(p.x[k]), double(p.y[k]), double(p.i[k]), zvalue(p.z[k])};
  f.d = 0;
  for (int c = 0; c < 3; ++c) f.colour[c] = double(p.colour[c]);
  f.opaque = p.opaque;
  f.protect = p.protect;
  f.id = UInt<16>(p.id);
  return f;
}

// ---- Exact coverage (the float reference's rule on integer vertices) -------------------------------

// Sample (sx, sy) in half units (2 x grid units, integers for N <= 1024) is covered when every
// edge function is positive, or zero on an edge whose inward gradient points along +x, or along +y
// for horizontal edges (symbolic perturbation: left and top edges inclusive, right and bottom edges
// exclusive). Zero-area polygons cover nothing.
struct ExactCoverage {
  int n = 0;
  std::int64_t x[kMaxVertices], y[kMaxVertices];  // half units
  int orient = 0;                                 // sign of the math-orientation area
  explicit ExactCoverage(const IntPolygon& p) {
    n = p.n;
    for (int k = 0; k < n; ++k) {
      x[k] = 2 * std::int64_t(p.x[k]);
      y[k] = 2 * std::int64_t(p.y[k]);
    }
    const std::int64_t a = shoelace2(p);
    orient = a > 0 ? 1 : a < 0 ? -1 : 0;
  }
  bool covers(std::int64_t sx, std::int64_t sy) const {
    if (orient == 0) return false;
    for (int k = 0; k < n; ++k) {
      const int k1 = k + 1 == n ? 0 : k + 1;
      const std::int64_t dx = x[k1] - x[k], dy = y[k1] - y[k];
      if (dx == 0 && dy == 0) continue;
      const std::int64_t e = orient * (dx * (sy - y[k]) - dy * (sx - x[k]));
      if (e < 0) return false;
      if (e == 0) {
        const std::int64_t gx = -orient * dy, gy = orient * dx;
        if (!(gx > 0 || (gx == 0 && gy > 0))) return false;
      }
    }
    return true;
  }
};

// ---- A random tiling of the screen -------------------------------------------------------------------

// The screen square [0, 4095]^2 as a G x G grid of cells, each split along a random diagonal into two
// triangles. Vertices are jittered (up to 0.9 of a cell; boundary vertices along their side only,
// corners fixed); a fifth of the interior vertices instead go onto, or one unit off, the opposite
// side of one of their triangles, which makes slivers and zero-area triangles. A move that would
// turn a triangle over is halved until it does not (the grid position itself never does: the
// vertex's neighbours were placed with it there). The result is a tiling: every triangle has a
// non-negative shoelace area and the areas sum to the square's (checked).
inline std::vector<IntPolygon> random_tiling(Rng& rng) {
  const int G = int(between(rng, 2, 9)), cell = 4095 / G, V = G + 1;
  std::vector<std::pair<int, int>> pos(std::size_t(V * V));
  auto at = [&](int a, int b) -> std::pair<int, int>& { return pos[std::size_t(a * V + b)]; };
  for (int a = 0; a <= G; ++a)
    for (int b = 0; b <= G; ++b) at(a, b) = {a == G ? 4095 : a * cell, b == G ? 4095 : b * cell};
  // Triangles as vertex indices (a * V + b); with Y down, (top-left, top-right, bottom-right) has a
  // positive shoelace sum.
  std::vector<std::array<int, 3>> tris;
  for (int a = 0; a < G; ++a)
    for (int b = 0; b < G; ++b) {
      const int p00 = a * V + b, p10 = (a + 1) * V + b, p11 = (a + 1) * V + b + 1, p01 = a * V + b + 1;
      if (below(rng, 2)) {
        tris.push_back({p00, p10, p11});
        tris.push_back({p00, p11, p01});
      } else {
        tris.push_back({p00, p10, p01});
        tris.push_back({p10, p11, p01});
      }
    }
  std::vector<std::vector<std::size_t>> incident(pos.size());
  for (std::size_t t = 0; t < tris.size(); ++t)
    for (int v : tris[t]) incident[std::size_t(v)].push_back(t);
  auto area2 = [&](const std::array<int, 3>& t) {
    std::int64_t s = 0;
    for (int k = 0; k < 3; ++k) {
      const auto& p = pos[std::size_t(t[std::size_t(k)])];
      const auto& q = pos[std::size_t(t[std::size_t((k + 1) % 3)])];
      s += std::int64_t(p.first) * q.second - std::int64_t(q.first) * p.second;
    }
    return s;
  };
  for (int a = 0; a <= G; ++a)
    for (int b = 0; b <= G; ++b) {
      const bool fix_x = a == 0 || a == G, fix_y = b == 0 || b == G;
      if (fix_x && fix_y) continue;
      const std::size_t v = std::size_t(a * V + b);
      const auto home = pos[v];
      std::pair<int, int> target = home;
      if (!fix_x && !fix_y && below(rng, 5) == 0) {  // onto the opposite side of one of its triangles
        const auto& t = tris[incident[v][std::size_t(below(rng, std::int64_t(incident[v].size())))]];
        int sx = 0, sy = 0;
        for (int w : t)
          if (std::size_t(w) != v) sx += pos[std::size_t(w)].first, sy += pos[std::size_t(w)].second;
        target = {sx / 2 + int(between(rng, -1, 1)), sy / 2 + int(between(rng, -1, 1))};
      } else {
        const int j = cell * 9 / 10;
        if (!fix_x) target.first += int(between(rng, -j, j));
        if (!fix_y) target.second += int(between(rng, -j, j));
      }
      for (int halving = 0; halving < 12; ++halving) {
        pos[v] = {std::clamp(target.first, 0, 4095), std::clamp(target.second, 0, 4095)};
        if (std::all_of(incident[v].begin(), incident[v].end(), [&](std::size_t t) { return area2(tris[t]) >= 0; }))
          break;
        pos[v] = home;
        target = {home.first + (target.first - home.first) / 2, home.second + (target.second - home.second) / 2};
      }
    }
  std::vector<IntPolygon> out;
  std::int64_t area = 0;
  for (const auto& t : tris) {
    IntPolygon p;
    p.n = 3;
    p.id = int(out.size());
    for (int k = 0; k < 3; ++k) {
      p.x[k] = pos[std::size_t(t[std::size_t(k)])].first;
      p.y[k] = pos[std::size_t(t[std::size_t(k)])].second;
      p.i[k] = int(below(rng, 256));
      p.z[k] = 127 * 128 + int(below(rng, 256));
    }
    p.colour[0] = p.id & 255;
    area += shoelace2(p);
    EXPECT_GE(shoelace2(p), 0);
    out.push_back(p);
  }
  EXPECT_EQ(area, std::int64_t(2) * 4095 * 4095);
  return out;
}

// ---- Formats ---------------------------------------------------------------------------------------

template <class Fmt>
struct FormatInfo {
  using P = FixedSegmentArith<Fmt>;
  static constexpr int kFx = P::X::frac_bits;          // X fractional bits
  static constexpr int kFs = P::Slope::frac_bits;      // Slope fractional bits
  static constexpr int kFi = P::Intensity::frac_bits;  // Intensity fractional bits
  static double lsb_x() { return std::ldexp(1.0, -kFx); }
  static double lsb_s() { return std::ldexp(1.0, -kFs); }
  static double lsb_i() { return std::ldexp(1.0, -kFi); }
};

}  // namespace cig::hls::segtest
