// Planted violation (verif/hls_subset/README.md): a do ... while loop.
// expect: while-loop
#pragma once

#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

// Position of the highest set bit of a 16-bit word, -1 for zero.
inline int planted_msb_top(const UInt<16>& x) {
  int msb = -1;
  int k = 0;  // planted-only
  do {  // clean: for (int k = 0; k < 16; ++k) {
    if (x.bit(k)) msb = k;
    ++k;  // planted-only
  } while (k < 16);  // clean: }
  return msb;
}

CIG_HLS_END_NAMESPACE
