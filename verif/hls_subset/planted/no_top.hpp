// Planted violation (verif/hls_subset/README.md): a kernel header without a top function (and not
// marked as a header of helpers).
// expect: top-function
#pragma once

#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

inline UInt<9> planted_add(const UInt<8>& a, const UInt<8>& b) { return a + b; }  // clean: inline UInt<9> planted_add_top(const UInt<8>& a, const UInt<8>& b) { return a + b; }

CIG_HLS_END_NAMESPACE
