// The 15-bit depth format of SPEC C: Z stays floating point, 8-bit exponent and 7-bit mantissa,
// no sign (Z > 0). In effect bfloat16 without its sign bit.
//
//   bits [14:7] exponent e, bias 127 (as in IEEE binary32, so conversion from binary32 or
//               binary64 is a re-bias and a mantissa rounding)
//   bits [6:0]  mantissa m, hidden leading one: value = 2^(e - 127) * (1 + m / 128)
//
// Every code is a normal number: there is no zero, infinity or NaN, because a depth is always
// positive and finite. The formatter maps depths below 2^-127 (and zero) to the smallest code
// (e = 0, m = 0, value 2^-127) and depths at or above the largest code's value to the largest
// code (e = 255, m = 127, value ~2^129). Codes compare in the same order as their values, so
// the raw 15-bit code is also a monotonic depth key.
#pragma once

#include "hls/types/bits.hpp"

CIG_HLS_BEGIN_NAMESPACE

struct ZFloat {
  UInt<15> bits;

  static constexpr int kMantissaBits = 7;
  static constexpr int kExponentBits = 8;
  static constexpr int kBias = 127;

  CIG_HLS_CONSTEXPR UInt<8> exponent() const { return bits.slice<14, 7>(); }
  CIG_HLS_CONSTEXPR UInt<7> mantissa() const { return bits.slice<6, 0>(); }
  // 1.m as an 8-bit integer (hidden one made explicit): value = significand * 2^(e - 127 - 7).
  CIG_HLS_CONSTEXPR UInt<8> significand() const { return UInt<8>(mantissa().value() | 0x80u); }
  static CIG_HLS_CONSTEXPR ZFloat from_fields(UInt<8> e, UInt<7> m) {
    ZFloat z;
    z.bits = UInt<15>((e.value() << 7) | m.value());
    return z;
  }
};

CIG_HLS_END_NAMESPACE
