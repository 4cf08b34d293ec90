// Synthesis top of the overload threshold (see syn/formatter_top.cpp for why it is at global scope).
#include "hls/segment/overload.hpp"

int overload_threshold_top(const cig::hls::OverloadCounts& c, int bank_capacity) {
  return cig::hls::overload_threshold_top(c, bank_capacity);
}
