// Synthesis top of the quadtree processing element (see syn/formatter_top.cpp for why it is at
// global scope).
#include "hls/quadtree/pe.hpp"

void quadtree_pe_top(const cig::hls::QuadWindow<cig::hls::DefaultQuadArith>& w, cig::hls::UInt<4> mask_word,
                     cig::hls::UInt<4> raster_log2,
                     cig::hls::QuadChild<cig::hls::DefaultQuadArith> (&children)[cig::hls::kQuadChildren]) {
  cig::hls::quadtree_pe_top(w, mask_word, raster_log2, children);
}
