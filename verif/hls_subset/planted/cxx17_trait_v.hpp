// Planted violation (verif/hls_subset/README.md): a C++17 `_v` trait (std::is_same_v), a name
// C++14's <type_traits> does not declare; hls/ is C++14, what Vitis HLS and Catapult both take.
// expect: compile
#pragma once

#include <type_traits>

#include "hls/types/bits.hpp"

CIG_HLS_BEGIN_NAMESPACE

inline UInt<8> planted_same_top(const UInt<8>& x) {
  static_assert(!std::is_same_v<UInt<8>, Int<8>>, "unsigned");  // clean: static_assert(!std::is_same<UInt<8>, Int<8>>::value, "unsigned");
  return x;
}

CIG_HLS_END_NAMESPACE
