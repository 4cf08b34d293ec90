// Planted violation (verif/hls_subset/README.md): a virtual member function.
// expect: virtual
#pragma once

#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

struct PlantedShader {
  UInt<8> gain;
  virtual UInt<16> shade(const UInt<8>& level) const { return level * gain; }  // clean: UInt<16> shade(const UInt<8>& level) const { return level * gain; }
};

inline UInt<16> planted_shade_top(const UInt<8>& level, const UInt<8>& gain) {
  PlantedShader s;
  s.gain = gain;
  return s.shade(level);
}

CIG_HLS_END_NAMESPACE
