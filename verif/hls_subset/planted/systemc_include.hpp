// Planted violation (verif/hls_subset/README.md): a library header outside hls/ and the allowed
// standard headers (SystemC is for the simulation mapping only, under CIG_HLS_SYSTEMC in
// hls/types/bits.hpp). The errors its own code raises in the synthesis build are not reported.
// expect: forbidden-header
#pragma once

#include <systemc>  // planted-only

#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

inline UInt<9> planted_add_top(const UInt<8>& a, const UInt<8>& b) { return a + b; }

CIG_HLS_END_NAMESPACE
