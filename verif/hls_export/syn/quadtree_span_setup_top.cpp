// Synthesis top of the quadtree span-piece setup (see syn/formatter_top.cpp for why it is at global
// scope).
#include "hls/quadtree/span_setup.hpp"

bool quadtree_span_setup_top(const cig::hls::FormattedPrimitive& f, const cig::hls::SpanPiece& piece,
                             cig::hls::UInt<4> raster_log2, cig::hls::QuadWindow<cig::hls::DefaultQuadArith>& root) {
  return cig::hls::quadtree_span_setup_top(f, piece, raster_log2, root);
}
