// Planted violation (verif/hls_subset/README.md): a non-const static local (hidden state).
// expect: static-local
#pragma once

#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

struct PlantedAccumulator {
  UInt<16> sum;
};

// Running sum of the samples seen so far.
inline UInt<16> planted_accumulate_top(const UInt<8>& sample, PlantedAccumulator& state) {
  static UInt<16> total;  // clean: UInt<16>& total = state.sum;
  total = wrap_unsigned<16>(total + sample);
  state.sum = total;
  return total;
}

CIG_HLS_END_NAMESPACE
