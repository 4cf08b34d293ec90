// Synthesis top of the quadtree pixel processor (see syn/formatter_top.cpp for why it is at global
// scope).
#include "hls/quadtree/pixel_processor.hpp"

cig::hls::PixelSampleMask quadtree_pixel_top(const cig::hls::QuadWindow<cig::hls::DefaultQuadArith>& px,
                                             cig::hls::PixelSampleMask samples,
                                             const cig::hls::QuadPixelTables<cig::hls::DefaultQuadArith>& t,
                                             const cig::hls::QuadLightCover<cig::hls::DefaultQuadArith>& lights,
                                             cig::hls::QuadPixelState<cig::hls::DefaultQuadArith>& st) {
  return cig::hls::quadtree_pixel_top(px, samples, t, lights, st);
}
