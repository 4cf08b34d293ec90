// Planted violation (verif/hls_subset/README.md): dynamic memory (new / delete).
// expect: dynamic-memory
#pragma once

#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

constexpr int kPlantedTaps = 8;

inline UInt<11> planted_sum_top(const UInt<8> (&in)[kPlantedTaps]) {
  UInt<8>* buffer = new UInt<8>[kPlantedTaps];  // clean: UInt<8> buffer[kPlantedTaps];
  UInt<11> sum;
  for (int k = 0; k < kPlantedTaps; ++k) buffer[k] = in[k];
  for (int k = 0; k < kPlantedTaps; ++k) sum = wrap_unsigned<11>(sum + buffer[k]);
  delete[] buffer;  // planted-only
  return sum;
}

CIG_HLS_END_NAMESPACE
