// Planted violation (verif/hls_subset/README.md): a std container (include and use).
// expect: forbidden-header
// expect: std-library
#pragma once

#include <vector>  // planted-only

#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

constexpr int kPlantedTaps = 4;

// Sum of four samples.
inline UInt<10> planted_sum_top(const UInt<8> (&in)[kPlantedTaps]) {
  std::vector<UInt<8>> taps(in, in + kPlantedTaps);  // clean: const UInt<8> (&taps)[kPlantedTaps] = in;
  UInt<10> sum;
  for (int k = 0; k < kPlantedTaps; ++k) sum = wrap_unsigned<10>(sum + taps[k]);
  return sum;
}

CIG_HLS_END_NAMESPACE
