// Synthesis top of the light-point segment generator (see syn/formatter_top.cpp for why it is at
// global scope).
#include "hls/segment/light_segments.hpp"

int light_segments_top(const cig::hls::FormattedPrimitive& light, cig::hls::UInt<4> raster_log2,
                       cig::hls::UInt<3> channel,
                       cig::hls::Segment<cig::hls::DefaultSegmentArith> (&out)[cig::hls::kMaxLightSegments]) {
  return cig::hls::light_segments_top(light, raster_log2, channel, out);
}
