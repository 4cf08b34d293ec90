// Double-precision twin of the formatter kernel (hls/formatter/formatter.hpp, SPEC C eq. 1): the
// same algorithm without quantization, and the bridge from the screen frame to the kernel's raw
// records.
//
//   x = clamp(2048*xs + 2047, 0, 4095)    y likewise (grid units, real)
//   i = clamp(256*is, 0, 255)             d = clamp(2048*ds, 0, 7)   (light points; 0 for polygons)
//   colour = clamp(255*c, 0, 255)         z = zs (unquantized)
// NaN propagates (std::clamp of NaN is NaN). The kernel's rounded words differ from these by at most
// half an LSB in X, Y, I, D and colour, and by a relative 2^-8 in Z (verif/kernels/test_formatter.cpp).
#pragma once

#include <cstdint>

#include "frame/screen_frame.hpp"
#include "hls/segment/records.hpp"

namespace cig {

double twin_grid(double s);         // X or Y from Xs or Ys
double twin_intensity(double is);   // I from Is
double twin_diameter(double ds);    // D from Ds
double twin_colour(double c);       // one colour component

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
