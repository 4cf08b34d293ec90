// Sample colour arithmetic shared by every raster engine's pixel stage (the segment processor's
// video channel, the quadtree raster processor's pixel processor): colour x I, fog by a table,
// the box filter over a pixel's 16 samples. One piece of code, so that two engines that see the
// same sample values produce the same bits.
//
// Formats:
//   Level      UInt<8>                          formatted colour / fog colour, 0..255
//   Sample     UFixed<16, 8, round, saturate>   a sample's colour component in output LSB, 8
//                                               fractional bits below the output LSB
//   FogFactor  UFixed<9, 1, round, saturate>    f in [0, 1], raw 0..256
//   FogTable   32768 FogFactors indexed by a 15-bit e8m7 code (of Z, or of 1/Z), loaded by the
//              host for each frame from the fog range ("haze as a function of Z", SPEC D)
#pragma once

// hls-subset-helper: the colour arithmetic shared by the video channel and the pixel processor.

#include "hls/formatter/sample_lattice.hpp"
#include "hls/types/fixed.hpp"
#include "hls/types/zfloat.hpp"

CIG_HLS_BEGIN_NAMESPACE

using SampleLevel = UInt<8>;
using SampleColour = UFixed<16, 8, Quant::kRound, Overflow::kSat>;
using FogFactor = UFixed<9, 1, Quant::kRound, Overflow::kSat>;

constexpr int kFogTableSize = 1 << 15;

struct FogTable {
  FogFactor f[kFogTableSize];
};

inline FogFactor fog_lookup(const FogTable& t, const ZFloat& code) { return t.f[code.bits.value()]; }

// colour x I (SPEC D: "colour = polygon colour x I"): c * I / 256 in output LSB, rounded half up
// to 8 fractional bits, saturated at 255.996. Intensity is any unsigned fixed format (0..256:
// full intensity 256 keeps the colour, so white stays 255).
template <class Intensity>
inline SampleColour shade(const SampleLevel& c, const Intensity& i) {
  const auto p = UFixed<8, 8>::from_raw(c) * i;  // UFixed<8 + W, 8 + I_int>: c * I, exact
  using Product = decltype(p);
  return SampleColour(UFixed<Product::width, Product::int_bits - 8>::from_raw(p.raw()));  // / 256
}

// Fog: s * (1 - f) + fog * f, exact, then rounded half up to the sample format.
inline SampleColour fog_mix(const SampleColour& s, const SampleLevel& fog, const FogFactor& f) {
  const auto one = FogFactor::from_raw_value(256);
  const auto keep = one - f;  // signed view, exact
  return SampleColour(to_signed(s) * keep + Fixed<9, 9>::from_raw(Int<9>(int(fog.value()))) * to_signed(f));
}

inline SampleColour level_sample(const SampleLevel& c) { return SampleColour(UFixed<8, 8>::from_raw(c)); }

// Box filter over the S x S = 4^t samples of a pixel (t = side_log2 <= 3). The sum of up to 64
// samples below 256 is exact in UFixed<22, 14>; the mean is the sum / 4^t, rounded half up, saturated
// to 255: the raw sum (8 fractional bits) shifted right by 8 + 2t with half an LSB added.
using BoxSum = UFixed<22, 14>;
inline UInt<8> resolve_box_sum(const BoxSum& sum, int side_log2) {
  const int shift = 8 + 2 * side_log2;
  const std::uint64_t mean = (std::uint64_t(sum.raw().value()) + (std::uint64_t{1} << (shift - 1))) >> shift;
  return UInt<8>(mean > 255u ? 255u : mean);
}
inline UInt<8> resolve_box(const SampleColour (&s)[kMaxSamplesPerPixel], int side_log2) {
  BoxSum sum;
  for (int k = 0; k < kMaxSamplesPerPixel; ++k) {
    if (k >= (1 << (2 * side_log2))) break;
    sum = BoxSum(sum + s[k]);
  }
  return resolve_box_sum(sum, side_log2);
}

CIG_HLS_END_NAMESPACE
