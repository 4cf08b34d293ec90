// Planted violation (verif/hls_subset/README.md): a floating-point literal (no float keyword).
// expect: floating-point
#pragma once

#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

// Scales an 8-bit level by 3/4.
inline UInt<8> planted_scale_top(const UInt<8>& level) {
  const std::uint64_t scaled = level.value() * 0.75;  // clean: const std::uint64_t scaled = level.value() * 3 / 4;
  return UInt<8>(scaled);
}

CIG_HLS_END_NAMESPACE
