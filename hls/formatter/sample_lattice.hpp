// The formatter grid and the sample lattice (SPEC C, seed 001 eq. 1): the geometry every raster
// engine shares. Stage C defines it once here; the segment processor (D), the quadtree raster
// processor (E) and the float reference (cmodel/reference/sample_lattice.hpp) all read it.
//
// Grid. X = 2048 Xs + 2047 (eq. 1): 4096 grid units across, Xs = -1 at X = -1, Xs = 1 at 4095.
//
// Raster. N = 2^n pixels (raster lines) a side, kMinRasterLog2 <= n <= kMaxRasterLog2, so a pixel
// is u = 4096 / N = 2^(12 - n) grid units; pixel p spans [u p - 1, u p - 1 + u).
//
// Samples. 4 x 4 per pixel at u p - 1 + (2 s + 1) u / 8, s = 0..3; numbered 0..4N-1 along each
// axis (sample k of the raster = sample k mod 4 of pixel k / 4). In *half units* (2 x grid units)
// sample k lies at
//     H_k = (u / 2) k + u / 4 - 2 = 2^(11 - n) k + 2^(10 - n) - 2,
// an integer for every N <= 1024, so every edge test against a formatted (integer) vertex is exact.
// At N = 512 the samples lie on the even grid units 8p, 8p + 2, 8p + 4, 8p + 6.
#pragma once

// hls-subset-helper: the grid and sample-lattice constants every stage after the formatter shares.

#include "hls/types/bits.hpp"

CIG_HLS_BEGIN_NAMESPACE

// ---- Formatter grid (eq. 1) ---------------------------------------------------------------------
constexpr int kGridScaleLog2 = 11;  // X = 2^11 Xs + 2047
constexpr int kGridUnits = 4096;    // grid units across the screen
constexpr int kGridOffset = 2047;
constexpr int kGridMax = kGridUnits - 1;  // formatted X, Y: UInt<12>, 0..4095
constexpr int kMaxLightDiameter = 7;      // D = 2048 Ds clamped to 0..7 grid units: UInt<3>

// ---- Raster limits ------------------------------------------------------------------------------
constexpr int kMinRasterLog2 = 4;   // N >= 16
constexpr int kMaxRasterLog2 = 10;  // N <= 1024 (H_k stays an integer)
constexpr int kMaxLines = 1 << kMaxRasterLog2;
constexpr int kSamplesPerSide = 4;  // 4 x 4 samples per pixel
constexpr int kSamplesPerPixel = kSamplesPerSide * kSamplesPerSide;
constexpr int kMaxLatticeSize = kMaxLines * kSamplesPerSide;  // samples per row or column, largest raster

// n of a raster of N = 2^n lines, or -1 when N is not a power of two up to 2^(kMaxRasterLog2 + 2)
// (the C model's largest raster, 4096, included). The one place a line count becomes its log2.
CIG_HLS_CONSTEXPR inline int raster_log2_of(int lines) {
  int log2 = -1;
  for (int k = 0; k <= kMaxRasterLog2 + 2; ++k)
    if (lines == (1 << k)) log2 = k;
  return log2;
}

// ---- Sample positions ----------------------------------------------------------------------------
// The lattice of one raster in half units: sample k (a row or a column) at
// H_k = k 2^log2_half_spacing + offset_half.
struct LatticeGeometry {
  int log2_half_spacing;  // log2(u / 2) = 11 - n
  int offset_half;        // u / 4 - 2 = 2^(10 - n) - 2
  static CIG_HLS_CONSTEXPR LatticeGeometry for_raster(int raster_log2) {
    return LatticeGeometry{kGridScaleLog2 - raster_log2, (1 << (kGridScaleLog2 - 1 - raster_log2)) - 2};
  }
  // H_k: the half-unit position of sample row (or column) k.
  CIG_HLS_CONSTEXPR int sample_half(int k) const { return k * (1 << log2_half_spacing) + offset_half; }
  // The first sample k with H_k >= h: ceil((h - offset) / 2^s) (any integer h, any sign).
  CIG_HLS_CONSTEXPR int first_sample_at_or_after_half(int h) const {
    const int t = h - offset_half;
    return t <= 0 ? -((-t) >> log2_half_spacing) : ((t + (1 << log2_half_spacing) - 1) >> log2_half_spacing);
  }
};

CIG_HLS_END_NAMESPACE
