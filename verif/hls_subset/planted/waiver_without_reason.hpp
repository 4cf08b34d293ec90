// Planted violation (verif/hls_subset/README.md): a waiver without a reason does not waive.
// expect: waiver
// expect: static-local
#pragma once

#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

// Running sum of the samples seen so far (the register is deliberate).
inline UInt<16> planted_accumulate_top(const UInt<8>& sample) {
  static UInt<16> total;  // hls-subset-ok:  // clean: static UInt<16> total;  // hls-subset-ok: the accumulator register of this kernel
  total = wrap_unsigned<16>(total + sample);
  return total;
}

CIG_HLS_END_NAMESPACE
