// Span-piece setup (SPEC E, the setup for a polygon that snapping made non-convex): each span piece
// of the polygon (hls/formatter/span_pieces.hpp) becomes a level-0 window of its own, whose edges
// are the piece's left and right polygon edge and its first and last sample row, four exact edge
// lines, and whose parameter planes are the polygon's. The PEs, the masks and the pixel processor
// treat it as any convex piece.
#pragma once

#include "hls/formatter/span_pieces.hpp"
#include "hls/quadtree/setup.hpp"
#include "hls/types/top_ports.hpp"

CIG_HLS_BEGIN_NAMESPACE

// The positions of a setup input as the formatter's output (what the span-piece split reads).
template <class P>
void span_input_from_setup(const QuadPrimitiveInput<P>& in, FormattedPrimitive& f) {
  f.n = in.n;
  for (int k = 0; k < kMaxVertices; ++k) {
    f.v[k].x = in.v[k].x;
    f.v[k].y = in.v[k].y;
  }
}

// Setup of one span piece of a polygon that snapping made non-convex: edges 0 and 1 are the left
// and right polygon edges (the left one owns its ties, the right one does not: the crossing rule's
// span [x_left, x_right)), edges 2 and 3 the piece's first and last sample row; the parameter
// planes are the polygon's, fitted on its fan triangle (0, k, k + 1) of largest area (every piece
// of the polygon gets the same planes). ok is false when every fan triangle is degenerate (the
// vertices on one line: the polygon covers nothing).
template <class P>
void quadtree_setup_span_piece(const QuadPrimitiveInput<P>& in, const SpanPiece& piece, int raster_log2,
                               QuadWindow<P>& root, bool& ok, int side_log2 = kDefaultSideLog2) {
  const LatticeGeometry g = LatticeGeometry::for_raster(raster_log2, side_log2);
  const int n = int(in.n.value());
  int hx[kMaxVertices], hy[kMaxVertices];
  int e_min = 255;
  for (int k = 0; k < kMaxVertices; ++k) {
    hx[k] = 2 * int(in.v[k].x.value());
    hy[k] = 2 * int(in.v[k].y.value());
  }
  for (int k = 0; k < kMaxVertices; ++k) {
    if (k >= n) break;
    const int e = P::depth_exponent(in.v[k].z);
    if (e < e_min) e_min = e;
  }
  const int best = largest_fan_triangle(hx, hy, n);
  ok = best > 0;
  if (!ok) return;
  int idx[kQuadMaxEdges] = {0, best, best + 1, 0, 0, 0, 0, 0};
  UInt<3> bbox;
  quad_detail::setup_piece(in, hx, hy, idx, 3, g, e_min, root, bbox, ok);
  if (!ok) return;
  const int lt = int(piece.left_top.value()), lb = int(piece.left_bottom.value());
  const int rt = int(piece.right_top.value()), rb = int(piece.right_bottom.value());
  QuadPolygon<P>& poly = root.poly;
  Int<29> c[kQuadMaxEdges];
  quad_detail::edge_line(hx[lt], hy[lt], hx[lb], hy[lb], -1, g.log2_half_spacing, g.offset_half, poly.a[0], poly.b[0],
                         c[0]);
  quad_detail::edge_line(hx[rt], hy[rt], hx[rb], hy[rb], 1, g.log2_half_spacing, g.offset_half, poly.a[1], poly.b[1],
                         c[1]);
  for (int k = 2; k < kQuadMaxEdges; ++k) {
    poly.a[k] = EdgeGradient(0);
    poly.b[k] = EdgeGradient(k == 2 ? 1 : (k == 3 ? -1 : 0));
    c[k] = Int<29>(k == 2 ? -int(piece.row_first.value()) : (k == 3 ? int(piece.row_last.value()) : 0));
  }
  for (int k = 0; k < kQuadMaxEdges; ++k) root.d[k] = quad_detail::root_coverage(poly.a[k], poly.b[k], c[k], g);
  poly.edge_count = UInt<4>(4);
  // The start window: the piece's rows of the whole polygon's box (its samples lie in both).
  int box[4] = {hx[0], hx[0], hy[0], hy[0]};
  for (int k = 1; k < kMaxVertices; ++k) {
    if (k >= n) break;
    if (hx[k] < box[0]) box[0] = hx[k];
    if (hx[k] > box[1]) box[1] = hx[k];
    if (hy[k] < box[2]) box[2] = hy[k];
    if (hy[k] > box[3]) box[3] = hy[k];
  }
  int i0, i1, j0, j1;
  quad_detail::box_samples(box[0], box[1], g, i0, i1);
  quad_detail::box_samples(box[2], box[3], g, j0, j1);
  if (j0 < int(piece.row_first.value())) j0 = int(piece.row_first.value());
  if (j1 > int(piece.row_last.value())) j1 = int(piece.row_last.value());
  quad_detail::set_start_window(i0, i1, j0, j1, g, poly);
}

// Top function (HLS): the default format; false when the polygon's vertices all lie on one line.
// Ports (hls/types/top_ports.hpp): name, direction, interface, C++ type.
#define CIG_HLS_PORTS_quadtree_span_setup_top(PORT, ARRAY, RESULT) \
  RESULT(bool)                                                     \
  PORT(f, in, ap_none, const FormattedPrimitive&)                  \
  PORT(piece, in, ap_none, const SpanPiece&)                       \
  PORT(raster_log2, in, ap_none, UInt<4>)                          \
  PORT(root, out, ap_vld, QuadWindow<DefaultQuadArith>&)
inline CIG_HLS_TOP(quadtree_span_setup_top) {
  QuadPrimitiveInput<DefaultQuadArith> in;
  quad_input_from_formatted(f, in);
  bool ok = false;
  quadtree_setup_span_piece(in, piece, int(raster_log2.value()), root, ok);
  return ok;
}

CIG_HLS_END_NAMESPACE
