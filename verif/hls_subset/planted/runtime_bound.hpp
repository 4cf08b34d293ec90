// Planted violation (verif/hls_subset/README.md): a loop bounded by a run-time value.
// expect: loop-bound
#pragma once

#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

constexpr int kPlantedMaxTaps = 16;

// Sum of the first n samples.
inline UInt<12> planted_sum_top(const UInt<8> (&in)[kPlantedMaxTaps], int n) {
  UInt<12> sum;
  for (int k = 0; k < n; ++k) {  // clean: for (int k = 0; k < kPlantedMaxTaps; ++k) {
    if (k >= n) break;
    sum = wrap_unsigned<12>(sum + in[k]);
  }
  return sum;
}

CIG_HLS_END_NAMESPACE
