// Synthesis top of the span-piece edge generator (see syn/formatter_top.cpp for why it is at
// global scope).
#include "hls/segment/span_piece_edges.hpp"

void span_piece_edges_top(const cig::hls::FormattedPrimitive& in, const cig::hls::SpanPiece& piece,
                          cig::hls::UInt<4> raster_log2, cig::hls::PolygonEdges<cig::hls::DefaultSegmentArith>& out) {
  cig::hls::span_piece_edges_top(in, piece, raster_log2, out);
}
