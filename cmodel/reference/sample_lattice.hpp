// Sample positions of the float reference, in double: the formatter's sample lattice
// (hls/formatter/sample_lattice.hpp, SPEC C), where every constant is defined.
//
// The formatter maps Xs in [-1, 1] to X = 2048*Xs + 2047, so the screen spans X in [-1, 4095].
// A raster of N pixels gives each pixel u = 4096/N grid units; pixel p spans [u*p - 1, u*p - 1 + u).
// Each pixel holds 4 x 4 samples, sample s at u*p - 1 + (2s + 1)*u/8 (stratified, centred in its
// cell). At N = 512 (u = 8) the samples lie on the even grid units 8p, 8p+2, 8p+4, 8p+6: integers,
// so on snapped vertices every edge test is exact.
//
// All coverage work happens in *sample coordinates*: sample (i, j) of the whole raster sits at
// (i, j), i, j in [0, 4N). The map from grid units is x = (X + 1 - u/8) * 4/u, a power-of-two
// scale and a dyadic offset, hence exact in double for snapped vertices.
#pragma once

#include "formatter/formatter_twin.hpp"
#include "hls/formatter/sample_lattice.hpp"

namespace cig {

constexpr int kSamplesPerSide = hls::kSamplesPerSide;
constexpr int kSamplesPerPixel = hls::kSamplesPerPixel;

// The float reference also takes other lattices (samples per side 1, 2, 4, 8, 16: 1 to 256 samples
// per pixel, the same stratified rule, sample s at u*p - 1 + (2s + 1)*u/(2 side)): a finer one is
// the ground truth of `cig sweep`, a coarser one shows what fewer samples cost.
constexpr int kMaxReferenceSideLog2 = 4;
constexpr int kMaxReferenceSamplesPerSide = 1 << kMaxReferenceSideLog2;

struct SampleLattice {
  int raster = 512;                           // N
  int side = kSamplesPerSide;                 // samples per pixel side
  int size() const { return raster * side; }  // samples per row and per column
  double units_per_pixel() const { return double(hls::kGridUnits) / raster; }
  // Grid units -> sample coordinates.
  double from_grid(double g) const {
    const double u = units_per_pixel();
    return (g + 1.0 - u / (2.0 * side)) * (side / u);
  }
  // Screen coordinate (Xs or Ys) -> sample coordinate.
  double from_screen(double s) const { return from_grid(grid_x(s)); }
  // Grid units (a length) -> sample units.
  double length_from_grid(double d) const { return d * (side / units_per_pixel()); }
};

}  // namespace cig
