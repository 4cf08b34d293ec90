// The formatter grid and the sample lattice (SPEC C, seed 001 eq. 1): the geometry every raster
// engine shares. Stage C defines it once here; the segment processor (D), the quadtree raster
// processor (E) and the float reference (cmodel/reference/sample_lattice.hpp) all read it.
//
// Grid. X = 2048 Xs + 2047 (eq. 1): 4096 grid units across, Xs = -1 at X = -1, Xs = 1 at 4095.
//
// Raster. N = 2^n pixels (raster lines) a side, kMinRasterLog2 <= n <= kMaxRasterLog2, so a pixel
// is u = 4096 / N = 2^(12 - n) grid units; pixel p spans [u p - 1, u p - 1 + u).
//
// Samples. S x S per pixel, S = 2^t (t = side_log2: 1, 4, 16 or 64 samples per pixel; the seeds'
// 4 x 4, t = 2, is the default and the RTL's), at u p - 1 + (2 s + 1) u / (2S), s = 0..S-1;
// numbered 0..SN-1 along each axis (sample k of the raster = sample k mod S of pixel k / S). In
// *half units* (2 x grid units) sample k lies at
//     H_k = (2u / S) k + u / S - 2 = 2^(13 - n - t) k + 2^(12 - n - t) - 2,
// an integer whenever the lattice has at most 4096 samples a side (n + t <= 12), so every edge
// test against a formatted (integer) vertex is exact. The lattice depends on n + t only: every
// width derived for the default lattice (n + 2 in 6..12) holds for any n + t in 6..12
// (kMinLatticeLog2..kMaxLatticeLog2). At N = 512, t = 2 the samples lie on the even grid units
// 8p, 8p + 2, 8p + 4, 8p + 6.
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
constexpr int kDefaultSideLog2 = 2;  // t: 4 x 4 samples per pixel, the seeds' lattice
// The largest lattice the kernels' storage is sized for (sample lanes, masks, line buffers): 8 x 8.
// An HLS build for one lattice sets it to that lattice's t (-DCIG_HLS_MAX_SIDE_LOG2=2 for the
// seeds' 4 x 4, as the RTL), so that no lane is synthesised that never works.
#ifndef CIG_HLS_MAX_SIDE_LOG2
#define CIG_HLS_MAX_SIDE_LOG2 3
#endif
constexpr int kMaxSideLog2 = CIG_HLS_MAX_SIDE_LOG2;
static_assert(kMaxSideLog2 >= kDefaultSideLog2 && kMaxSideLog2 <= 3, "the lattice is 4 x 4 to 8 x 8 samples a pixel");
constexpr int kSamplesPerSide = 1 << kDefaultSideLog2;
constexpr int kSamplesPerPixel = kSamplesPerSide * kSamplesPerSide;
constexpr int kMaxSamplesPerSide = 1 << kMaxSideLog2;
constexpr int kMaxSamplesPerPixel = kMaxSamplesPerSide * kMaxSamplesPerSide;
constexpr int kMinLatticeLog2 = kMinRasterLog2 + kDefaultSideLog2;  // n + t >= 6: the plane fit's 2^(7 - s)
constexpr int kMaxLatticeLog2 = kMaxRasterLog2 + kDefaultSideLog2;  // n + t <= 12: H_k an integer
constexpr int kMaxLatticeSize = 1 << kMaxLatticeLog2;               // samples per row or column, largest lattice
// A pixel's samples, one bit each (bit S dj + di): the quadtree's sample masks and pixel lanes.
using PixelSampleMask = UInt<kMaxSamplesPerPixel>;

// Whether the kernels take an N = 2^n raster with S = 2^t samples a side per pixel.
CIG_HLS_CONSTEXPR inline bool lattice_supported(int raster_log2, int side_log2) {
  return raster_log2 >= kMinRasterLog2 && raster_log2 <= kMaxRasterLog2 && side_log2 >= 0 &&
         side_log2 <= kMaxSideLog2 && raster_log2 + side_log2 >= kMinLatticeLog2 &&
         raster_log2 + side_log2 <= kMaxLatticeLog2;
}

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
  int log2_half_spacing;  // log2(2u / S) = 13 - n - t
  int offset_half;        // u / S - 2 = 2^(12 - n - t) - 2
  int raster_log2;        // n
  int side_log2;          // t: S = 2^t samples a side per pixel
  static CIG_HLS_CONSTEXPR LatticeGeometry for_raster(int raster_log2, int side_log2 = kDefaultSideLog2) {
    const int lattice_log2 = raster_log2 + side_log2;
    return LatticeGeometry{kGridScaleLog2 + 2 - lattice_log2, (1 << (kGridScaleLog2 + 1 - lattice_log2)) - 2,
                           raster_log2, side_log2};
  }
  CIG_HLS_CONSTEXPR int side() const { return 1 << side_log2; }                  // S
  CIG_HLS_CONSTEXPR int rows() const { return 1 << (raster_log2 + side_log2); }  // SN rows (and columns)
  // H_k: the half-unit position of sample row (or column) k.
  CIG_HLS_CONSTEXPR int sample_half(int k) const { return k * (1 << log2_half_spacing) + offset_half; }
  // The first sample k with H_k >= h: ceil((h - offset) / 2^s) (any integer h, any sign).
  CIG_HLS_CONSTEXPR int first_sample_at_or_after_half(int h) const {
    const int t = h - offset_half;
    return t <= 0 ? -((-t) >> log2_half_spacing) : ((t + (1 << log2_half_spacing) - 1) >> log2_half_spacing);
  }
};

CIG_HLS_END_NAMESPACE
