// Synthesis top of seed 002's pixel processor, one clock (W = 64; see syn/formatter_top.cpp for why
// it is at global scope).
#include "hls/invparam/pixel_processor.hpp"

cig::hls::PpOutputs<cig::hls::kPpTopWordBits> invparam_pixel_processor_top(
    cig::hls::PpState<cig::hls::kPpTopWordBits>& st, const cig::hls::Word<cig::hls::kPpTopWordBits>& input,
    const cig::hls::PpCtrl& ctrl) {
  return cig::hls::invparam_pixel_processor_top(st, input, ctrl);
}
