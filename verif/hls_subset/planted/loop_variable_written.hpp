// Planted violation (verif/hls_subset/README.md): a for loop whose body moves its own counter.
// expect: loop-bound
#pragma once

#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

constexpr int kPlantedTaps = 16;

// Sum of the samples; a zero sample also drops the sample after it.
inline UInt<12> planted_sum_top(const UInt<8> (&in)[kPlantedTaps]) {
  UInt<12> sum;
  // clean: bool skip = false;
  for (int k = 0; k < kPlantedTaps; ++k) {
    // clean: if (skip) { skip = false; continue; }
    sum = wrap_unsigned<12>(sum + in[k]);
    if (in[k].value() == 0) k += 1;  // clean: skip = in[k].value() == 0;
  }
  return sum;
}

CIG_HLS_END_NAMESPACE
