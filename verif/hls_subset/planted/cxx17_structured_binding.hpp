// Planted violation (verif/hls_subset/README.md): a C++17 structured binding; hls/ is C++14, what
// Vitis HLS and Catapult both take.
// expect: later-standard
#pragma once

#include "hls/types/bits.hpp"

CIG_HLS_BEGIN_NAMESPACE

struct PlantedHalves {
  UInt<8> high, low;
};

inline UInt<9> planted_halves_top(const PlantedHalves& h) {
  const auto [high, low] = h;  // clean: const UInt<8> high = h.high, low = h.low;
  return UInt<9>(high.value() + low.value());
}

CIG_HLS_END_NAMESPACE
