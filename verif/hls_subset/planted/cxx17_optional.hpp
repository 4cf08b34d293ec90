// Planted violation (verif/hls_subset/README.md): C++17's std::optional (its header, and a std
// library type in a kernel); hls/ is C++14 on the allowed standard headers only.
// expect: forbidden-header
// expect: std-library
#pragma once

#include <optional>  // planted-only

#include "hls/types/bits.hpp"

CIG_HLS_BEGIN_NAMESPACE

inline UInt<8> planted_first_top(const UInt<8>& x, bool valid) {
  std::optional<UInt<8>> v;  // clean: UInt<8> v;
  if (valid) v = x;
  return valid ? *v : UInt<8>(0);  // clean: return valid ? v : UInt<8>(0);
}

CIG_HLS_END_NAMESPACE
