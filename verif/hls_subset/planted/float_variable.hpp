// Planted violation (verif/hls_subset/README.md): a float variable in a kernel.
// expect: floating-point
#pragma once

#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

// Scales an 8-bit level by 3/4.
inline UInt<8> planted_scale_top(const UInt<8>& level) {
  const float scaled = level.value() * 3 / 4;  // clean: const std::uint64_t scaled = level.value() * 3 / 4;
  return UInt<8>(static_cast<std::uint64_t>(scaled));
}

CIG_HLS_END_NAMESPACE
