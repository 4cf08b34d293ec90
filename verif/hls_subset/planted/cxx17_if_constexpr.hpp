// Planted violation (verif/hls_subset/README.md): a C++17 construct (if constexpr); hls/ is C++14,
// what Vitis HLS and Catapult both take.
// expect: later-standard
#pragma once

#include "hls/types/bits.hpp"

CIG_HLS_BEGIN_NAMESPACE

template <int W>
inline UInt<W> planted_low_bits_top(const UInt<W>& x) {
  if constexpr (W > 8) return UInt<W>(x.value() & 0xff);  // clean: if (W > 8) return UInt<W>(x.value() & 0xff);
  return x;
}

CIG_HLS_END_NAMESPACE
