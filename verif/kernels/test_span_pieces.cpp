// Span pieces (hls/formatter/span_pieces.hpp) against an exact crossing-number count: on polygons
// that snapping to the formatter grid makes non-convex, self-intersecting or reversed, and on wild
// random polygons, every sample of the lattice is covered by exactly as many pieces as the crossing
// rule says (0 or 1: the pieces are disjoint), at several rasters and sample lattices (1 to 64 samples per pixel).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "hls/formatter/span_pieces.hpp"
#include "hls/quadtree/pe.hpp"
#include "hls/quadtree/span_setup.hpp"
#include "hls/segment/segment_generator.hpp"
#include "hls/segment/span_piece_edges.hpp"
#include "segment_test_support.hpp"

namespace cig::hls::segtest {
namespace {

// Half-unit position of sample k on an N = 2^log2 raster with S = 2^side_log2 samples a side per
// pixel (README: pixel p spans grid units [u p - 1, u p - 1 + u), u = 4096 / N, its S samples at
// u p - 1 + (2 s + 1) u / (2S)).
std::int64_t sample_half(int log2, std::int64_t k, int side_log2 = kDefaultSideLog2) {
  const std::int64_t u = 4096 >> log2, side = std::int64_t{1} << side_log2;
  return k * (2 * u / side) + u / side - 2;
}

// The lattice of test polygon `index`: S = 1, 2, 4 and 8 samples a side in turn, with SN = 2^lattice_log2.
int side_log2_for(int index) { return (index / 3) % 4; }

// The crossing rule on the sample perturbed to (x + e, y + e^2): an odd number of edges cross
// the row right of it (half-open Y ranges; a crossing at x exactly lies left of x + e).
bool odd_crossings(const IntPolygon& p, std::int64_t sx, std::int64_t sy) {
  bool inside = false;
  for (int k = 0; k < p.n; ++k) {
    const int k1 = (k + 1) % p.n;
    const std::int64_t ax = 2 * p.x[k], ay = 2 * p.y[k], bx = 2 * p.x[k1], by = 2 * p.y[k1];
    if ((ay > sy) == (by > sy)) continue;
    const i128 num = i128(ax - sx) * (by - ay) + i128(sy - ay) * (bx - ax);
    if ((by > ay) ? num > 0 : num < 0) inside = !inside;
  }
  return inside;
}

// x of the polygon edge between vertices a and b at half-unit height y, compared with sx:
// sign of x_edge(y) - sx.
int edge_minus_x(const IntPolygon& p, int a, int b, std::int64_t sx, std::int64_t sy) {
  std::int64_t xa = 2 * p.x[a], ya = 2 * p.y[a], xb = 2 * p.x[b], yb = 2 * p.y[b];
  if (ya > yb) {
    std::swap(xa, xb);
    std::swap(ya, yb);
  }
  const i128 d = i128(xa - sx) * (yb - ya) + i128(sy - ya) * (xb - xa);  // (x_edge - sx) (yb - ya)
  return d > 0 ? 1 : (d < 0 ? -1 : 0);
}

bool edge_holds_row(const IntPolygon& p, int a, int b, std::int64_t sy) {
  const std::int64_t ya = 2 * p.y[a], yb = 2 * p.y[b];
  return std::min(ya, yb) <= sy && sy < std::max(ya, yb);
}

// Every sample of the raster: pieces covering it (left boundary inclusive, right exclusive) against
// the crossing rule. Returns the samples covered.
long check_polygon(const IntPolygon& p, int log2, int t) {
  auto pieces = std::make_unique<SpanPieces>();
  split_into_span_pieces(fixed_input(p), log2, *pieces);
  const int m = 4 << log2;
  int x0 = 4095, x1 = 0, y0 = 4095, y1 = 0;
  for (int k = 0; k < p.n; ++k) {
    x0 = std::min(x0, p.x[k]), x1 = std::max(x1, p.x[k]);
    y0 = std::min(y0, p.y[k]), y1 = std::max(y1, p.y[k]);
  }
  const int u = 4096 >> log2;
  const int i0 = std::max(0, 4 * (x0 / u) - 4), i1 = std::min(m - 1, 4 * (x1 / u) + 8);
  const int j0 = std::max(0, 4 * (y0 / u) - 4), j1 = std::min(m - 1, 4 * (y1 / u) + 8);
  long covered = 0;
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const std::int64_t sx = sample_half(log2, i), sy = sample_half(log2, j);
      const bool want = odd_crossings(p, sx, sy);
      int got = 0;
      if (pieces->convex) {
        got = ExactCoverage(p).covers(sx, sy) ? 1 : 0;
      } else {
        for (int k = 0; k < int(pieces->count.value()); ++k) {
          const SpanPiece& pc = pieces->piece[k];
          if (j < pc.row_first.value() || j > pc.row_last.value()) continue;
          const int lt = int(pc.left_top.value()), lb = int(pc.left_bottom.value());
          const int rt = int(pc.right_top.value()), rb = int(pc.right_bottom.value());
          EXPECT_TRUE(edge_holds_row(p, lt, lb, sy) && edge_holds_row(p, rt, rb, sy))
              << "polygon " << t << " piece " << k << " row " << j;
          if (edge_minus_x(p, lt, lb, sx, sy) <= 0 && edge_minus_x(p, rt, rb, sx, sy) > 0) ++got;
        }
      }
      if (got != (want ? 1 : 0)) {
        ADD_FAILURE() << "polygon " << t << " at N = " << (1 << log2) << ", sample (" << i << ", " << j << "): " << got
                      << " pieces, crossing rule " << want << " (convex " << pieces->convex << ", "
                      << pieces->count.value() << " pieces)";
        return covered;
      }
      covered += want;
    }
  return covered;
}

bool turns_one_way(const IntPolygon& p) {
  int positive = 0, negative = 0;
  for (int k = 0; k < p.n; ++k) {
    const int a = k, b = (k + 1) % p.n, c = (k + 2) % p.n;
    const std::int64_t t =
        std::int64_t(p.x[b] - p.x[a]) * (p.y[c] - p.y[b]) - std::int64_t(p.y[b] - p.y[a]) * (p.x[c] - p.x[b]);
    positive += t > 0;
    negative += t < 0;
  }
  return shoelace2(p) != 0 && (positive == 0 || negative == 0);
}

// A thin convex polygon with extra, nearly collinear vertices on its long sides, snapped to whole
// grid units (eq. 1's rounding); kept when the snap made it non-convex.
bool snap_to_non_convex(Rng& rng, IntPolygon& p) {
  auto unit = [&] { return double(rng() >> 11) * 0x1.0p-53; };
  const double cx = 40 + 4000 * unit(), cy = 40 + 4000 * unit();
  const double angle = 6.283185307179586 * unit(), length = 4 + 300 * unit() * unit();
  const double width = 2.5 * unit() * unit(), bulge = 0.4 * unit();
  const int per_side = 1 + int(unit() * 6);
  p = IntPolygon();
  for (int side = 0; side < 2; ++side)
    for (int k = 0; k <= per_side; ++k) {
      const double f = side == 0 ? double(k) / per_side : 1 - double(k) / per_side;
      const double along = (f - 0.5) * length, across = (side == 0 ? 1 : -1) * (width / 2 + bulge * f * (1 - f));
      const int x = int(std::lround(cx + along * std::cos(angle) - across * std::sin(angle)));
      const int y = int(std::lround(cy + along * std::sin(angle) + across * std::cos(angle)));
      if (p.n > 0 && x == p.x[p.n - 1] && y == p.y[p.n - 1]) continue;
      p.x[p.n] = std::clamp(x, 0, 4095);
      p.y[p.n] = std::clamp(y, 0, 4095);
      ++p.n;
    }
  while (p.n > 1 && p.x[p.n - 1] == p.x[0] && p.y[p.n - 1] == p.y[0]) --p.n;
  return p.n >= 4 && !turns_one_way(p);
}

TEST(SpanPieces, SnapToNonConvexEqualsCrossingRule) {
  Rng rng(0x5A4);
  long covered = 0, zero_area = 0;
  int kept = 0;
  for (int t = 0; kept < 600 && t < 100000; ++t) {
    IntPolygon p;
    if (!snap_to_non_convex(rng, p)) continue;
    if (kept % 2) std::reverse(p.x, p.x + p.n), std::reverse(p.y, p.y + p.n);
    zero_area += shoelace2(p) == 0;
    for (int log2 = 6; log2 <= 10; log2 += 2) covered += check_polygon(p, log2, kept);
    if (HasFailure()) return;
    ++kept;
  }
  EXPECT_EQ(kept, 600);
  EXPECT_GT(covered, 10000);
  EXPECT_GT(zero_area, 0);  // bow-ties of zero signed area among them
}

// Random vertices in a small box: self-intersecting stars with many crossings (the worst case for
// the number of pieces), and polygons folded onto themselves.
TEST(SpanPieces, WildPolygonsEqualCrossingRule) {
  Rng rng(0x3117);
  long covered = 0;
  int most = 0;
  for (int t = 0; t < 400; ++t) {
    IntPolygon p;
    p.n = 3 + int(below(rng, 14));
    const int box = t % 2 ? 40 : 600, x0 = int(below(rng, 4096 - box)), y0 = int(below(rng, 4096 - box));
    for (int k = 0; k < p.n; ++k) {
      p.x[k] = x0 + int(below(rng, box));
      p.y[k] = y0 + int(below(rng, box));
    }
    for (int log2 = 4; log2 <= 8; log2 += 2) covered += check_polygon(p, log2, t);
    auto pieces = std::make_unique<SpanPieces>();
    split_into_span_pieces(fixed_input(p), 8, *pieces);
    most = std::max(most, int(pieces->count.value()));
    if (HasFailure()) return;
  }
  EXPECT_GT(covered, 10000);
  EXPECT_LE(most, kMaxSpanPieces);
  EXPECT_GT(most, 20);  // stars with many crossings were among them
}

TEST(SpanPieces, ConvexPolygonsTakeTheConvexPath) {
  Rng rng(0xC0);
  for (int t = 0; t < 2000; ++t) {
    const IntPolygon p = random_polygon(rng, Shape::kAny, t);
    auto pieces = std::make_unique<SpanPieces>();
    split_into_span_pieces(fixed_input(p), 9, *pieces);
    if (shoelace2(p) != 0) { ASSERT_TRUE(pieces->convex) << "polygon " << t; }
    check_polygon(p, 6, t);
    if (HasFailure()) return;
  }
}

// The engines' tests' polygons: every third a random star in a 150-unit box (wild), the others a
// thin polygon the snap made non-convex. False when no such polygon came of this draw.
bool bent_polygon(Rng& rng, bool wild, IntPolygon& p) {
  if (!wild) return snap_to_non_convex(rng, p);
  p = IntPolygon();
  p.n = 3 + int(below(rng, 14));
  const int x0 = int(below(rng, 3900)), y0 = int(below(rng, 3900));
  for (int k = 0; k < p.n; ++k) p.x[k] = x0 + int(below(rng, 150)), p.y[k] = y0 + int(below(rng, 150));
  return true;
}

// ---- The quadtree raster processor on span pieces ------------------------------------------------

using QP = DefaultQuadArith;

QuadPrimitiveInput<QP> quad_input(const IntPolygon& p) {
  QuadPrimitiveInput<QP> in;
  quad_input_from_formatted(fixed_input(p), in);
  return in;
}

// Samples covered by the setup and the PE (a walk of the covered windows down to the pixels, no
// masks) of every span piece, counted per sample: SN x SN.
std::vector<int> quadtree_samples(const IntPolygon& p, int log2, int side_log2, int& pieces_out) {
  const int m = 1 << (log2 + side_log2), side_px = 1 << side_log2;
  std::vector<int> got(std::size_t(m) * std::size_t(m), 0);
  auto pieces = std::make_unique<SpanPieces>();
  split_into_span_pieces(fixed_input(p), log2, *pieces, side_log2);
  pieces_out = pieces->convex ? -1 : int(pieces->count.value());
  if (pieces->convex) return got;
  const QuadPrimitiveInput<QP> in = quad_input(p);
  std::vector<QuadWindow<QP>> stack;
  for (int k = 0; k < int(pieces->count.value()); ++k) {
    QuadWindow<QP> root;
    bool ok = false;
    quadtree_setup_span_piece(in, pieces->piece[k], log2, root, ok, side_log2);
    if (ok) stack.push_back(root);
  }
  while (!stack.empty()) {
    const QuadWindow<QP> w = stack.back();
    stack.pop_back();
    const int level = int(w.level.value()) + 1, side = side_px << (log2 - level);
    for (int q = 0; q < 4; ++q) {
      QuadChild<QP> c;
      evaluate_child(w, q, log2, false, c, side_log2);
      if (!c.covered) continue;
      if (level < log2) {
        stack.push_back(c.window);
        continue;
      }
      const int x0 = (2 * int(w.x.value()) + (q & 1)) * side, y0 = (2 * int(w.y.value()) + (q >> 1)) * side;
      for (int b = 0; b < side_px * side_px; ++b)
        if ((c.samples.value() >> b) & 1u)
          ++got[std::size_t(y0 + (b >> side_log2)) * std::size_t(m) + std::size_t(x0 + (b & (side_px - 1)))];
    }
  }
  return got;
}

TEST(SpanPieces, QuadtreeCoversTheCrossingRule) {
  Rng rng(0x9AD);
  long covered = 0;
  int polygons = 0;
  for (int t = 0; polygons < 300 && t < 100000; ++t) {
    IntPolygon p;
    const bool wild = t % 3 == 0;
    if (!bent_polygon(rng, wild, p)) continue;
    p.opaque = true;
    for (int k = 0; k < p.n; ++k) p.z[k] = 127 << 7, p.i[k] = 128;
    const int t2 = side_log2_for(polygons), log2 = 7 + polygons % 3 - t2;
    int pieces = 0;
    const std::vector<int> got = quadtree_samples(p, log2, t2, pieces);
    if (pieces < 0) continue;  // convex after all (a wild one): the convex setup's tests cover it
    const int m = 1 << (log2 + t2);
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        const bool want = odd_crossings(p, sample_half(log2, i, t2), sample_half(log2, j, t2));
        ASSERT_EQ(got[std::size_t(j) * std::size_t(m) + std::size_t(i)], want ? 1 : 0)
            << "polygon " << polygons << " (" << (wild ? "wild" : "snapped") << ", " << pieces
            << " pieces) at N = " << (1 << log2) << ", " << (1 << t2) << " samples a side, sample (" << i << ", " << j
            << ")";
        covered += want;
      }
    ++polygons;
  }
  EXPECT_EQ(polygons, 300);
  EXPECT_GT(covered, 2000);
}

// ---- The segment processor on span pieces ---------------------------------------------------------

using SP = DefaultSegmentArith;

// Samples covered by the edge generator's span pieces and the segment generator's segments (their
// X at each row to the first column at or after it, as the video channel draws), counted per
// sample: SN x SN.
std::vector<int> segment_samples(const IntPolygon& p, int log2, int side_log2) {
  const int m = 1 << (log2 + side_log2);
  std::vector<int> got(std::size_t(m) * std::size_t(m), 0);
  auto pieces = std::make_unique<SpanPieces>();
  const FormattedPrimitive f = fixed_input(p);
  split_into_span_pieces(f, log2, *pieces, side_log2);
  const LatticeGeometry g = LatticeGeometry::for_raster(log2, side_log2);
  auto edges = std::make_unique<PolygonEdges<SP>>();
  auto segments = std::make_unique<std::array<Segment<SP>, kMaxLines>>();
  auto& out = *reinterpret_cast<Segment<SP>(*)[kMaxLines]>(segments->data());
  for (int k = 0; k < int(pieces->count.value()); ++k) {
    generate_span_piece_edges<SP>(f, pieces->piece[k], log2, *edges, side_log2);
    const int count = generate_segments<SP>(*edges, log2, UInt<3>(0), false, out, side_log2);
    for (int t = 0; t < count; ++t) {
      const Segment<SP>& s = out[t];
      for (int r = int(s.row_first.value()); r <= int(s.row_last.value()); ++r) {
        const int row = g.side() * int(s.line.value()) + r;
        const int i0 = std::max(0, SP::first_column_at_or_after(g, s.xl[r]));
        const int i1 = std::min(m - 1, SP::first_column_at_or_after(g, s.xr[r]) - 1);
        for (int i = i0; i <= i1; ++i) ++got[std::size_t(row) * std::size_t(m) + std::size_t(i)];
      }
    }
  }
  return got;
}

TEST(SpanPieces, SegmentProcessorCoversTheCrossingRule) {
  Rng rng(0x5E6);
  long covered = 0;
  int polygons = 0;
  for (int t = 0; polygons < 300 && t < 100000; ++t) {
    IntPolygon p;
    const bool wild = t % 3 == 0;
    if (!bent_polygon(rng, wild, p)) continue;
    if (turns_one_way(p)) continue;  // convex: the convex edge generator's tests cover it
    const int t2 = side_log2_for(polygons), log2 = 7 + polygons % 4 - t2;
    const std::vector<int> got = segment_samples(p, log2, t2);
    const int m = 1 << (log2 + t2);
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        const bool want = odd_crossings(p, sample_half(log2, i, t2), sample_half(log2, j, t2));
        ASSERT_EQ(got[std::size_t(j) * std::size_t(m) + std::size_t(i)], want ? 1 : 0)
            << "polygon " << polygons << " (" << (wild ? "wild" : "snapped") << ") at N = " << (1 << log2) << ", "
            << (1 << t2) << " samples a side, sample (" << i << ", " << j << ")";
        covered += want;
      }
    ++polygons;
  }
  EXPECT_EQ(polygons, 300);
  EXPECT_GT(covered, 2000);
}

}  // namespace
}  // namespace cig::hls::segtest
