// Synthesis top of the video channel (see syn/formatter_top.cpp for why it is at global scope).
#include "hls/segment/video_channel.hpp"

int video_channel_top(cig::hls::UInt<10> line, cig::hls::UInt<4> raster_log2,
                      const cig::hls::SegmentMemory<cig::hls::DefaultSegmentArith>& m,
                      const cig::hls::VideoTables<cig::hls::DefaultSegmentArith>& t,
                      cig::hls::LineBuffer<cig::hls::DefaultSegmentArith>& w, cig::hls::PixelLine& out) {
  return cig::hls::video_channel_top(line, raster_log2, m, t, w, out);
}
