// Planted violation (verif/hls_subset/README.md): a recursive function (found in the call graph
// GCC emits; the source scan does not look for it).
// expect: recursion
#pragma once

#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

namespace planted_detail {
// Number of set bits in the low n bits of v.
inline int popcount_low(std::uint64_t v, int n) {
  return n <= 0 ? 0 : int((v >> (n - 1)) & 1u) + popcount_low(v, n - 1);  // clean: int c = 0; for (int k = 0; k < 64; ++k) c += k < n ? int((v >> k) & 1u) : 0; return c;
}
}  // namespace planted_detail

inline UInt<5> planted_popcount_top(const UInt<16>& x) { return UInt<5>(planted_detail::popcount_low(x.value(), 16)); }

CIG_HLS_END_NAMESPACE
