// Span pieces: the exact coverage of a formatted polygon that snapping made non-convex,
// self-intersecting or reversed, as disjoint pieces that the raster engines draw like convex
// polygons (SPEC C; the rule is the README's crossing rule, cmodel/reference/coverage.hpp).
//
// Eq. 1 snaps vertices to the formatter grid; a thin convex polygon can come out with a reflex
// vertex or as a bow-tie. Such a polygon covers the samples whose point perturbed to (x + e, y + e^2)
// has an odd crossing number: on sample row j the edges whose Y range [Y_top, Y_bottom) holds the
// row cross it, and between the 1st and 2nd, the 3rd and 4th, ... crossing (left end inclusive,
// right end exclusive) the polygon covers. The order of the crossings changes only at rows where an
// edge starts or ends or where two edges cross, so the rows fall into slabs of constant order, and
// every slab into spans bounded by one edge on the left and one on the right. A span piece is such
// a span over consecutive rows (spans of adjacent slabs between the same two edges merge): at most
// one left and one right edge, a first and a last sample row. Pieces are disjoint (each sample row
// is split into disjoint spans) and together cover exactly the crossing rule's samples; each
// boundary is an edge of the polygon between two formatted (integer) vertices, so a piece's edge
// tests are exact and keep the tie rule.
//
// A convex polygon (every turn the same way, Y changing direction twice) is left to the engines'
// convex path (count 0, convex true): its crossing-rule coverage is its edge functions' coverage.
// So is a flat one (every vertex on one line), which covers nothing and is dropped as degenerate.
//
// Arithmetic: half units (2 X, 2 Y: 0..8190) and sample rows; the x of an edge at a row is the
// rational (x_top dy + (y - y_top) dx) / dy, compared by cross-multiplication in 64-bit integers
// (|.| < 2^13 * 2^14 * 2^14). Bounds: n <= 16 edges give at most 2 x 16 start/end rows and
// 16 x 15 / 2 crossing rows, so at most kMaxSpanEvents slab bounds and 8 spans per slab.
#pragma once

#include <cstdint>

#include "hls/formatter/records.hpp"
#include "hls/types/top_ports.hpp"

CIG_HLS_BEGIN_NAMESPACE

constexpr int kMaxSpanEvents = 2 * kMaxVertices + kMaxVertices * (kMaxVertices - 1) / 2;  // 152
constexpr int kMaxSpansPerRow = kMaxVertices / 2;
constexpr int kMaxSpanPieces = (kMaxSpanEvents - 1) * kMaxSpansPerRow;  // 1208

struct SpanPiece {
  UInt<4> left_top, left_bottom;    // left boundary: the edge between these vertices (of the input)
  UInt<4> right_top, right_bottom;  // right boundary
  Int<13> row_first, row_last;      // global sample rows 0..SN-1, inclusive
};

struct SpanPieces {
  bool convex = true;  // true: no pieces, the engines' convex path covers the polygon exactly
  UInt<11> count;
  SpanPiece piece[kMaxSpanPieces];
};

namespace span_detail {

// An edge of the polygon, top vertex a (smaller Y), in half units, with its sample rows.
struct SpanEdge {
  int top, bottom;  // vertex indices of the input
  int xa, ya, dx, dy;
  int row_first, row_last;
};

// x of edge e at half-unit height y, as the fraction num / e.dy.
inline std::int64_t x_numerator(const SpanEdge& e, int y) {
  return std::int64_t(e.xa) * e.dy + std::int64_t(y - e.ya) * e.dx;
}

// Sign of x_p(y) - x_q(y).
inline int compare_at(const SpanEdge& p, const SpanEdge& q, int y) {
  const std::int64_t d = x_numerator(p, y) * q.dy - x_numerator(q, y) * p.dy;
  return d > 0 ? 1 : (d < 0 ? -1 : 0);
}

// Floor of a / b, b > 0.
inline std::int64_t floor_div(std::int64_t a, std::int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

// The first row after the rows both edges cross on which their order is the reverse of their order
// on the first shared row, or -1. x_p - x_q is linear in the row: f(j) = k0 + k1 j (times dy_p dy_q).
inline int crossing_row(const SpanEdge& p, const SpanEdge& q, const LatticeGeometry& g) {
  const int first = p.row_first > q.row_first ? p.row_first : q.row_first;
  const int last = p.row_last < q.row_last ? p.row_last : q.row_last;
  if (first >= last) return -1;
  const int y0 = g.sample_half(first);
  const std::int64_t f0 = x_numerator(p, y0) * q.dy - x_numerator(q, y0) * p.dy;
  const std::int64_t step =
      (std::int64_t(p.dx) * q.dy - std::int64_t(q.dx) * p.dy) * (std::int64_t(1) << g.log2_half_spacing);
  const int s0 = f0 > 0 ? 1 : (f0 < 0 ? -1 : (step > 0 ? 1 : -1));
  if (step == 0 || s0 * step >= 0) return -1;
  // Smallest t > 0 with s0 (f0 + step t) < 0.
  const std::int64_t t = floor_div(s0 * f0, -s0 * step) + 1;
  return t <= std::int64_t(last - first) ? first + int(t) : -1;
}

}  // namespace span_detail

// True when the polygon (in half units, m vertices, no repeated neighbours) is convex: every turn
// the same way (or straight) as the nonzero signed area, and Y changes direction at most twice.
inline bool span_polygon_is_convex(const int (&hx)[kMaxVertices], const int (&hy)[kMaxVertices], int m) {
  std::int64_t area2 = 0;
  for (int k = 0; k < kMaxVertices; ++k) {
    if (k >= m) break;
    const int k1 = k + 1 == m ? 0 : k + 1;
    area2 += std::int64_t(hx[k]) * hy[k1] - std::int64_t(hx[k1]) * hy[k];
  }
  if (area2 == 0) return false;
  int y_turns = 0, last_dy = 0;
  for (int k = 0; k < 2 * kMaxVertices; ++k) {  // twice around: the direction before vertex 0 too
    if (k >= 2 * m) break;
    const int a = k % m, b = (k + 1) % m, c = (k + 2) % m;
    const std::int64_t turn =
        std::int64_t(hx[b] - hx[a]) * (hy[c] - hy[b]) - std::int64_t(hy[b] - hy[a]) * (hx[c] - hx[b]);
    if ((turn > 0 && area2 < 0) || (turn < 0 && area2 > 0)) return false;
    const int dy = hy[b] - hy[a];
    if (dy == 0) continue;
    if (last_dy != 0 && (dy > 0) != (last_dy > 0) && k >= m) ++y_turns;
    last_dy = dy;
  }
  return y_turns <= 2;
}

// True when every vertex lies on one line: the polygon covers nothing, and the engines' convex
// path drops it as degenerate.
inline bool span_polygon_is_flat(const int (&hx)[kMaxVertices], const int (&hy)[kMaxVertices], int m) {
  for (int k = 2; k < kMaxVertices; ++k) {
    if (k >= m) break;
    if (std::int64_t(hx[1] - hx[0]) * (hy[k] - hy[0]) != std::int64_t(hy[1] - hy[0]) * (hx[k] - hx[0])) return false;
  }
  return true;
}

namespace span_detail {

// Phase 1: the vertices in half units without repeated neighbours (the formatter can merge two),
// with their index in the input. Returns their number.
template <class Q>
int kept_vertices(const FormattedPrimitiveT<Q>& in, int (&hx)[kMaxVertices], int (&hy)[kMaxVertices],
                  int (&src)[kMaxVertices]) {
  int m = 0;
  for (int k = 0; k < kMaxVertices; ++k) {
    hx[k] = hy[k] = src[k] = 0;
    if (k >= int(in.n.value())) continue;
    const int x = 2 * int(in.v[k].x.value()), y = 2 * int(in.v[k].y.value());
    if (m > 0 && x == hx[m - 1] && y == hy[m - 1]) continue;
    hx[m] = x;
    hy[m] = y;
    src[m] = k;
    ++m;
  }
  for (int k = 0; k < kMaxVertices; ++k) {
    if (m <= 1 || !(hx[m - 1] == hx[0] && hy[m - 1] == hy[0])) break;
    --m;
  }
  return m;
}

// Phase 2: the edges that cross at least one sample row, top vertex first. Returns their number.
inline int crossing_edges(const int (&hx)[kMaxVertices], const int (&hy)[kMaxVertices], const int (&src)[kMaxVertices],
                          int m, const LatticeGeometry& g, int rows, SpanEdge (&edge)[kMaxVertices]) {
  int ne = 0;
  for (int k = 0; k < kMaxVertices; ++k) {
    if (k >= m) break;
    const int k1 = k + 1 == m ? 0 : k + 1;
    if (hy[k] == hy[k1]) continue;
    const bool down = hy[k] < hy[k1];
    const int a = down ? k : k1, b = down ? k1 : k;
    SpanEdge e{src[a], src[b], hx[a], hy[a], hx[b] - hx[a], hy[b] - hy[a], 0, 0};
    e.row_first = g.first_sample_at_or_after_half(hy[a]);
    e.row_last = g.first_sample_at_or_after_half(hy[b]) - 1;
    if (e.row_first < 0) e.row_first = 0;
    if (e.row_last > rows - 1) e.row_last = rows - 1;
    if (e.row_first > e.row_last) continue;
    edge[ne++] = e;
  }
  return ne;
}

// Phase 3: the slab bounds, sorted: rows where an edge starts or ends, or where two edges change
// order. Returns their number (repeats included).
inline int slab_bounds(const SpanEdge (&edge)[kMaxVertices], int ne, const LatticeGeometry& g,
                       int (&event)[kMaxSpanEvents]) {
  int events = 0;
  for (int k = 0; k < kMaxVertices; ++k) {
    if (k >= ne) break;
    event[events++] = edge[k].row_first;
    event[events++] = edge[k].row_last + 1;
    for (int l = 0; l < kMaxVertices; ++l) {
      if (l >= k) break;
      const int r = crossing_row(edge[k], edge[l], g);
      if (r >= 0) event[events++] = r;
    }
  }
  for (int k = 1; k < kMaxSpanEvents; ++k) {  // insertion sort
    if (k >= events) break;
    const int v = event[k];
    int j = k;
    for (int s = 0; s < kMaxSpanEvents; ++s) {
      if (j == 0 || event[j - 1] <= v) break;
      event[j] = event[j - 1];
      --j;
    }
    event[j] = v;
  }
  return events;
}

// Phase 4a: the edges crossing the slab's rows in order of x on its first row, then on its last
// (edges cannot cross inside a slab). Returns their number.
inline int slab_order(const SpanEdge (&edge)[kMaxVertices], int ne, int first, int last, const LatticeGeometry& g,
                      int (&order)[kMaxVertices]) {
  const int y_first = g.sample_half(first), y_last = g.sample_half(last);
  int active = 0;
  for (int k = 0; k < kMaxVertices; ++k) {
    if (k >= ne) break;
    if (edge[k].row_first > first || edge[k].row_last < first) continue;
    int j = active++;
    for (int t = 0; t < kMaxVertices; ++t) {
      if (j == 0) break;
      const SpanEdge& o = edge[order[j - 1]];
      const int c = compare_at(o, edge[k], y_first);
      if (c < 0 || (c == 0 && compare_at(o, edge[k], y_last) <= 0)) break;
      order[j] = order[j - 1];
      --j;
    }
    order[j] = k;
  }
  return active;
}

// Phase 4b: one span of a slab as a piece: the piece of the slab above between the same two edges
// grows down, or a new piece starts. Returns the piece's index.
inline int add_span(const SpanEdge& l, const SpanEdge& r, int first, int last, const int (&above)[kMaxSpansPerRow],
                    int above_count, SpanPieces& out, int& count) {
  for (int q = 0; q < kMaxSpansPerRow; ++q) {
    if (q >= above_count) break;
    SpanPiece& pc = out.piece[above[q]];
    if (int(pc.row_last.value()) == first - 1 && int(pc.left_top.value()) == l.top &&
        int(pc.left_bottom.value()) == l.bottom && int(pc.right_top.value()) == r.top &&
        int(pc.right_bottom.value()) == r.bottom) {
      pc.row_last = Int<13>(last);
      return above[q];
    }
  }
  SpanPiece& pc = out.piece[count];
  pc.left_top = UInt<4>(l.top);
  pc.left_bottom = UInt<4>(l.bottom);
  pc.right_top = UInt<4>(r.top);
  pc.right_bottom = UInt<4>(r.bottom);
  pc.row_first = Int<13>(first);
  pc.row_last = Int<13>(last);
  return count++;
}

}  // namespace span_detail

// The span pieces of one formatted polygon on the lattice of an N = 2^raster_log2 raster.
template <class Q>
void split_into_span_pieces(const FormattedPrimitiveT<Q>& in, int raster_log2, SpanPieces& out,
                            int side_log2 = kDefaultSideLog2) {
  using span_detail::SpanEdge;
  const LatticeGeometry g = LatticeGeometry::for_raster(raster_log2, side_log2);
  int hx[kMaxVertices], hy[kMaxVertices], src[kMaxVertices];
  const int m = span_detail::kept_vertices(in, hx, hy, src);
  out.count = UInt<11>(0);
  out.convex = m < 3 || span_polygon_is_convex(hx, hy, m) || span_polygon_is_flat(hx, hy, m);
  if (out.convex) return;
  SpanEdge edge[kMaxVertices];
  const int ne = span_detail::crossing_edges(hx, hy, src, m, g, g.rows(), edge);
  int event[kMaxSpanEvents];
  const int events = span_detail::slab_bounds(edge, ne, g, event);
  // Each slab: its crossings paired left to right into spans.
  int count = 0;
  int above[kMaxSpansPerRow] = {}, here[kMaxSpansPerRow] = {};  // the pieces of the slab above, of this slab
  int above_count = 0;
  for (int s = 0; s < kMaxSpanEvents - 1; ++s) {
    if (s + 1 >= events) break;
    const int first = event[s], last = event[s + 1] - 1;
    if (first > last) continue;  // repeated bound
    int order[kMaxVertices];
    const int active = span_detail::slab_order(edge, ne, first, last, g, order);
    int here_count = 0;
    for (int span = 0; span < kMaxSpansPerRow; ++span) {
      if (2 * span + 1 >= active) break;
      here[here_count++] = span_detail::add_span(edge[order[2 * span]], edge[order[2 * span + 1]], first, last, above,
                                                 above_count, out, count);
    }
    for (int q = 0; q < kMaxSpansPerRow; ++q) above[q] = here[q];
    above_count = here_count;
  }
  out.count = UInt<11>(count);
}

// Top function (HLS): the split of one formatted polygon, shared by both raster engines' setups.
// Ports (hls/types/top_ports.hpp): name, direction, interface, C++ type.
#define CIG_HLS_PORTS_span_pieces_top(PORT, ARRAY, RESULT) \
  RESULT(void)                                             \
  PORT(in, in, ap_none, const FormattedPrimitive&)         \
  PORT(raster_log2, in, ap_none, UInt<4>)                  \
  PORT(out, out, ap_vld, SpanPieces&)
inline CIG_HLS_TOP(span_pieces_top) { split_into_span_pieces(in, int(raster_log2.value()), out); }

CIG_HLS_END_NAMESPACE
