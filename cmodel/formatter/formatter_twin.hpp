// Stage C in the C model: the double-precision twin of the formatter kernel
// (hls/formatter/formatter.hpp, SPEC C eq. 1), the same algorithm without quantization; the
// bridge from the screen frame to the kernel's raw records; and the formatter grid in double
// (grid_x, the snap of a whole frame) for the float reference. Every constant comes from
// hls/formatter/sample_lattice.hpp.
//
//   x = clamp(2048*xs + 2047, 0, 4095)    y likewise (grid units, real)
//   i = clamp(256*is, 0, 255)             d = clamp(2048*ds, 0, 7)   (light points; 0 for polygons)
//   colour = clamp(255*c, 0, 255)         z = zs (unquantized)
// NaN propagates (std::clamp of NaN is NaN). The kernel's rounded words differ from these by at most
// half an LSB in X, Y, I, D and colour, and by a relative 2^-8 in Z (verif/kernels/test_formatter.cpp).
#pragma once

#include <cstdint>

#include "frame/screen_frame.hpp"
#include "hls/formatter/records.hpp"

namespace cig {

// Formatter grid (eq. 1): X = 2048*Xs + 2047, Y = 2048*Ys + 2047, 4096 units per screen.
constexpr double kGridScale = double(1 << hls::kGridScaleLog2);
constexpr double kGridOffset = hls::kGridOffset;
constexpr int kGridMax = hls::kGridMax;
inline double grid_x(double xs) { return kGridScale * xs + kGridOffset; }
// Light-point diameter in grid units, D = 2048*Ds clamped to 0..7 (eq. 1).
constexpr double kMaxLightDiameterUnits = hls::kMaxLightDiameter;

// The formatter grid's width in bits per axis: eq. 1's X = 2048 Xs + 2047 is the seed's 12-bit grid
// (1/8 pixel at 512 lines). The sub-pixel knob (--engine-opt subpixel=B: 1/2^B pixel) generalises
// eq. 1 to a g-bit grid, X_g = 2^(g-1) Xs + 2^(g-1) - 1, g = log2(raster) + B. The fixed engines'
// widths are derived for g <= 12 (a coarser grid is a subset of the 12-bit one: X = 2^(12-g)(X_g + 1)
// - 1 is exact there); the float reference takes finer grids too.
constexpr int kSeedGridBits = hls::kGridScaleLog2 + 1;
constexpr int kMaxGridBits = 20;  // the float reference's finest grid (1/2^11 pixel at 512 lines)

// Snaps positions to the g-bit formatter grid (round half away from zero of eq. 1 at g bits), then
// clamps them to the 12-bit grid's 0..4095 (so that every grid keeps the seed's screen edges), and
// light diameters to whole 12-bit units 0..7, leaving everything else as it is: the float reference
// on a snapped frame sees exactly the positions a fixed-point engine sees. A snapped coordinate is
// a dyadic rational with at most g + 1 significant bits: exact in binary64, and the formatter
// kernel maps it to the same X (eq. 1 of an exact integer).
ScreenFrame snap_to_formatter_grid(const ScreenFrame& f, int grid_bits = kSeedGridBits);
double snap_grid_coordinate(double s, int grid_bits = kSeedGridBits);  // Xs or Ys -> snapped Xs or Ys

double twin_grid(double s);        // X or Y from Xs or Ys
double twin_intensity(double is);  // I from Is
double twin_diameter(double ds);   // D from Ds
double twin_colour(double c);      // one colour component

struct TwinVertex {
  double x = 0, y = 0, i = 0, z = 0;
};

struct TwinPrimitive {
  bool is_light = false;
  int n = 0;
  TwinVertex v[hls::kMaxVertices];  // n used (a light: v[0] is its centre)
  double d = 0;
  double colour[3] = {0, 0, 0};
  bool opaque = true, protect = false;
  std::uint16_t id = 0;
};

TwinPrimitive formatter_twin(const ScreenPolygon& p, std::uint16_t id);
TwinPrimitive formatter_twin(const ScreenLightPoint& l, std::uint16_t id);

#ifndef CIG_HLS_SYSTEMC
// Bridge to the kernel (native type configuration only: cig_cmodel is built natively, and a
// SystemC-typed translation unit has differently named hls:: records). Doubles are copied bit for
// bit. A polygon must have 1..kMaxVertices vertices (std::invalid_argument otherwise); a light
// point has n = 1, its centre in v[0] and its intensity in v[0].is.
hls::RawPrimitive raw_from_polygon(const ScreenPolygon& p, std::uint16_t id);
hls::RawPrimitive raw_from_light(const ScreenLightPoint& l, std::uint16_t id);
// The exact value of an e8m7 depth code: 2^(e - 127) * (1 + m/128).
double zfloat_to_double(hls::ZFloat z);
#endif

}  // namespace cig
