// Planted violation (verif/hls_subset/README.md): an iostream include (not even used).
// expect: forbidden-header
#pragma once

#include <iostream>  // planted-only

#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

inline UInt<9> planted_add_top(const UInt<8>& a, const UInt<8>& b) { return a + b; }

CIG_HLS_END_NAMESPACE
