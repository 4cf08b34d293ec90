// Synthesis top of the edge generator (see syn/formatter_top.cpp for why it is at global scope).
#include "hls/segment/edge_generator.hpp"

void edge_generator_top(const cig::hls::FormattedPrimitive& in, cig::hls::UInt<4> raster_log2,
                        cig::hls::PolygonEdges<cig::hls::DefaultSegmentArith>& out) {
  cig::hls::edge_generator_top(in, raster_log2, out);
}
