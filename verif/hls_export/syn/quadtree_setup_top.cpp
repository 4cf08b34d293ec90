// Synthesis top of the quadtree setup (see syn/formatter_top.cpp for why it is at global scope).
#include "hls/quadtree/setup.hpp"

void quadtree_setup_top(const cig::hls::FormattedPrimitive& f, cig::hls::UInt<4> raster_log2,
                        cig::hls::QuadSetup<cig::hls::DefaultQuadArith>& out) {
  cig::hls::quadtree_setup_top(f, raster_log2, out);
}
