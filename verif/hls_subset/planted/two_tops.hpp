// Planted violation (verif/hls_subset/README.md): two top functions in one kernel header.
// expect: top-function
#pragma once

#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

inline UInt<9> planted_add_top(const UInt<8>& a, const UInt<8>& b) { return a + b; }
inline Int<9> planted_sub_top(const UInt<8>& a, const UInt<8>& b) { return a - b; }  // clean: inline Int<9> planted_sub(const UInt<8>& a, const UInt<8>& b) { return a - b; }

CIG_HLS_END_NAMESPACE
