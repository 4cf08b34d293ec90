// Planted violation (verif/hls_subset/README.md): <cassert> (a run-time check that calls into the
// C library); its follow-on compile errors are not reported separately.
// expect: forbidden-header
#pragma once

#include <cassert>  // planted-only

#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

inline UInt<9> planted_add_top(const UInt<8>& a, const UInt<8>& b) {
  assert(a.value() < 200);  // planted-only
  return a + b;
}

CIG_HLS_END_NAMESPACE
