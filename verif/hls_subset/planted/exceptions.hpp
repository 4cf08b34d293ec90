// Planted violation (verif/hls_subset/README.md): an exception.
// expect: exceptions
#pragma once

#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

inline UInt<8> planted_div_top(const UInt<8>& a, const UInt<8>& b) {
  if (b.value() == 0) throw 0;  // clean: if (b.value() == 0) return UInt<8>(255);
  return div_trunc(a, b);
}

CIG_HLS_END_NAMESPACE
