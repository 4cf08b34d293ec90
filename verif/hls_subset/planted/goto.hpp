// Planted violation (verif/hls_subset/README.md): goto.
// expect: goto
#pragma once

#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

inline int planted_first_zero_top(const UInt<16>& x) {
  int found = -1;
  for (int k = 0; k < 16; ++k) {
    if (!x.bit(k)) {
      found = k;
      goto done;  // clean: break;
    }
  }
done:  // planted-only
  return found;
}

CIG_HLS_END_NAMESPACE
