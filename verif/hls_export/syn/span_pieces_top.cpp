// Synthesis top of the span-piece split (see syn/formatter_top.cpp for why it is at global scope).
#include "hls/formatter/span_pieces.hpp"

void span_pieces_top(const cig::hls::FormattedPrimitive& in, cig::hls::UInt<4> raster_log2, cig::hls::SpanPieces& out) {
  cig::hls::span_pieces_top(in, raster_log2, out);
}
