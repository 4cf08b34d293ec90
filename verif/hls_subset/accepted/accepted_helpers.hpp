// Accepted forms (verif/hls_subset/README.md): a header of shared helpers, marked as such, so it
// needs no top function (and may not define one).
// hls-subset-helper: helpers of accepted_kernel.hpp, which holds the top function
#pragma once

#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

// Bit reversal: the loop bound is the template parameter W.
template <int W>
CIG_HLS_CONSTEXPR UInt<W> accepted_reverse(const UInt<W>& x) {
  UInt<W> r;
  for (int i = 0; i < W; ++i) r = r.with_bit(W - 1 - i, x.bit(i));
  return r;
}

CIG_HLS_END_NAMESPACE
