// Planted violation (verif/hls_subset/README.md): two functions that call each other, one of
// them a template (the cycle is between instantiations).
// expect: recursion
#pragma once

#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

namespace planted_detail {
template <int W>
int odd_bits(const UInt<W>& x, int k);

// Set bits at even positions >= k plus the odd ones above.
template <int W>
int even_bits(const UInt<W>& x, int k) {
  if (k >= W) return 0;
  return (x.bit(k) ? 1 : 0) + odd_bits(x, k + 1);  // clean: return x.bit(k) ? 1 : 0;
}
template <int W>
int odd_bits(const UInt<W>& x, int k) {
  if (k >= W) return 0;
  return (x.bit(k) ? 1 : 0) + even_bits(x, k + 1);  // clean: return x.bit(k) ? 1 : 0;
}
}  // namespace planted_detail

inline int planted_bits_top(const UInt<12>& x) { return planted_detail::even_bits(x, 0) + planted_detail::odd_bits(x, 1); }

CIG_HLS_END_NAMESPACE
