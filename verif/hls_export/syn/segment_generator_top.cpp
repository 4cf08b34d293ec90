// Synthesis top of the segment generator (see syn/formatter_top.cpp for why it is at global scope).
#include "hls/segment/segment_generator.hpp"

int segment_generator_top(const cig::hls::PolygonEdges<cig::hls::DefaultSegmentArith>& in,
                          cig::hls::UInt<4> raster_log2, cig::hls::UInt<3> channel,
                          cig::hls::Segment<cig::hls::DefaultSegmentArith> (&out)[cig::hls::kMaxLines]) {
  return cig::hls::segment_generator_top(in, raster_log2, channel, out);
}
