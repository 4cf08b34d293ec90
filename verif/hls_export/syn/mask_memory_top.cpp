// Synthesis top of the priority-mask memory (see syn/formatter_top.cpp for why it is at global scope).
#include "hls/quadtree/mask_memory.hpp"

cig::hls::UInt<5> mask_memory_top(cig::hls::MaskMemory& m, cig::hls::UInt<4> level, cig::hls::UInt<10> x,
                                  cig::hls::UInt<10> y, cig::hls::UInt<2> child) {
  return cig::hls::mask_memory_top(m, level, x, y, child);
}
