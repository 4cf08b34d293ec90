// Synthesis top of the Y sorter (see syn/formatter_top.cpp for why it is at global scope).
#include "hls/segment/y_sorter.hpp"

bool y_sorter_top(const cig::hls::Segment<cig::hls::DefaultSegmentArith>& s,
                  cig::hls::SegmentMemory<cig::hls::DefaultSegmentArith>& m) {
  return cig::hls::y_sorter_top(s, m);
}
