// Synthesis top of the formatter: the kernel's top at global scope, the name set_top uses and the
// function the testbench calls (so that C/RTL co-simulation replaces it).
#include "hls/formatter/formatter.hpp"

void formatter_top(const cig::hls::RawPrimitive& in, cig::hls::FormattedPrimitive& out) {
  cig::hls::formatter_top(in, out);
}
