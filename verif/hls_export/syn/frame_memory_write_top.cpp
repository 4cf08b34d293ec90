// Synthesis top of the frame memory write port (see syn/formatter_top.cpp for why it is at global scope).
#include "hls/segment/frame_memory.hpp"

bool frame_memory_write_top(const cig::hls::PolygonEdges<cig::hls::DefaultSegmentArith>& e,
                            cig::hls::FrameMemory<cig::hls::DefaultSegmentArith>& m) {
  return cig::hls::frame_memory_write_top(e, m);
}
