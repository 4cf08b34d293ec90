// Span-piece edges (SPEC D, the edge generator for a polygon that snapping made non-convex): each
// span piece of the polygon (hls/formatter/span_pieces.hpp) becomes a frame-memory entry of its own,
// the polygon's header over the piece's rows and one edge on each side, so the segment generator
// and the video channel draw it as they draw a convex polygon.
#pragma once

#include "hls/formatter/span_pieces.hpp"
#include "hls/segment/edge_generator.hpp"
#include "hls/types/top_ports.hpp"

CIG_HLS_BEGIN_NAMESPACE

// One span piece of a polygon that snapping made non-convex (hls/formatter/span_pieces.hpp): the
// polygon's header with the piece's rows, and its left and right polygon edge as one-edge chains
// over those rows (the first crossing at the piece's first row, as the preprocessor computes it).
template <class P, class Q>
void generate_span_piece_edges(const FormattedPrimitiveT<Q>& in, const SpanPiece& piece, int raster_log2,
                               PolygonEdges<P>& out, int side_log2 = kDefaultSideLog2) {
  const LatticeGeometry g = LatticeGeometry::for_raster(raster_log2, side_log2);
  const int rows = g.rows();
  PolygonHeader<P>& h = out.h;
  detail::polygon_header(in, h);
  P::fit_planes(in, raster_log2, true, h.planes, side_log2);
  const int first = int(piece.row_first.value()), last = int(piece.row_last.value());
  const int ends[2][2] = {{int(piece.left_top.value()), int(piece.left_bottom.value())},
                          {int(piece.right_top.value()), int(piece.right_bottom.value())}};
  for (int side = 0; side < 2; ++side) {
    Edge<P>* chain = side == 0 ? out.left : out.right;
    UInt<5>& count = side == 0 ? h.left_count : h.right_count;
    const FormattedVertexT<Q>& a = in.v[ends[side][0]];
    const FormattedVertexT<Q>& b = in.v[ends[side][1]];
    detail::add_chain_edge<P>(a, b, g, rows, chain, count);
    if (count.value() == 0) continue;
    Edge<P>& e = chain[0];
    e.row_first = first;
    e.row_last = last;
    e.x_first = P::crossing(g, a.x, a.y, b.x, b.y, first);
  }
  out.valid = h.left_count.value() == 1 && h.right_count.value() == 1;
  h.row_first = first;
  h.row_last = last;
  detail::count_lines(h, side_log2);
}

// Top function (HLS): the default format.
// Ports (hls/types/top_ports.hpp): name, direction, interface, C++ type.
#define CIG_HLS_PORTS_span_piece_edges_top(PORT, ARRAY, RESULT) \
  RESULT(void)                                                  \
  PORT(in, in, ap_none, const FormattedPrimitive&)              \
  PORT(piece, in, ap_none, const SpanPiece&)                    \
  PORT(raster_log2, in, ap_none, UInt<4>)                       \
  PORT(out, out, ap_vld, PolygonEdges<DefaultSegmentArith>&)
inline CIG_HLS_TOP(span_piece_edges_top) {
  generate_span_piece_edges<DefaultSegmentArith>(in, piece, int(raster_log2.value()), out);
}

CIG_HLS_END_NAMESPACE
