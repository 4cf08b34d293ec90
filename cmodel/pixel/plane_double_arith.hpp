// The double-precision twin of the pixel stages' plane arithmetic (hls/pixel/attribute_planes.hpp):
// plugged into the same kernels (the quadtree setup and pixel processor, the segment processor's
// plane mode), it gives the same algorithm with no quantization of the planes, the values, the fog
// or the colour. Value units as in the fixed policy, except W: the twin's W is 1/Z itself
// (w_exponent 0). Vertex values are the formatter twin's (256 Is in [0, 256], Zs).
#pragma once

#include <algorithm>
#include <cmath>

#include "hls/pixel/attribute_planes.hpp"

namespace cig {

struct PlaneDoubleArith {
  using VertexI = double;  // 256 Is, clamped to [0, 256] (the formatter twin)
  using VertexZ = double;  // Zs
  using Value = double;
  using Gradient = double;
  using Param = double;
  using NewellSum = double;
  using SumValue = double;
  using Sample = double;
  using Intensity = double;
  using FogFactorType = double;
  struct FogTable {
    double start = 1e30, end = 2e30;
  };

  // The box filter's output: the mean of the 4^side_log2 samples' 8-bit values, rounded (half away
  // from zero) and clamped to 255 (the twins' resolve; the fixed kernels' is hls/pixel/). The
  // division by a power of two is exact (as ldexp), without a library call.
  static hls::UInt<8> box_mean(double sum, int side_log2) {
    return hls::UInt<8>(int(std::lround(std::clamp(sum / double(1 << (2 * side_log2)), 0.0, 255.0))));
  }

  static Value intensity_value(double i) { return i; }
  static int depth_exponent(double) { return 0; }
  static int w_exponent(int) { return 0; }
  static Value inverse_depth_value(double z, int) { return 1.0 / z; }
  static NewellSum newell_x(const hls::Int<15>& dhy, double v0, double v1) { return double(dhy.value()) * (v0 + v1); }
  static NewellSum newell_y(const hls::Int<15>& shx, double v0, double v1) { return double(shx.value()) * (v0 - v1); }
  static NewellSum newell_add(double a, double t) { return a + t; }
  static SumValue value_add(double a, double v) { return a + v; }
  static void plane(double nx, double ny, const hls::Int<34>& nz, double sum_v, const hls::Int<24>& si7,
                    const hls::Int<24>& sj7, int n, int ls, double& d, double& e, double& f) {
    const double s = std::ldexp(1.0, ls), area = double(nz.value());
    d = -nx * s / area;
    e = -ny * s / area;
    f = (sum_v - d * double(si7.value()) / 128.0 - e * double(sj7.value()) / 128.0) / n;
  }
  static Param at_sample(double f, double d, double e, int di, int dj) { return f + d * di + e * dj; }
  static Intensity intensity(double v) { return std::clamp(v, 0.0, 256.0); }
  static FogFactorType fog_factor(const FogTable& t, double w, const hls::Int<10>&) {
    if (!(w > 0)) return 1.0;
    return std::clamp((1.0 / w - t.start) / (t.end - t.start), 0.0, 1.0);
  }
  static Sample sample_colour(const hls::UInt<8>& c, double i, double f, const hls::UInt<8>& fog) {
    return double(c.value()) * i / 256.0 * (1.0 - f) + double(fog.value()) * f;
  }
  // The segment twin's levels are doubles already.
  static Sample sample_colour(double c, double i, double f, double fog) { return c * i / 256.0 * (1.0 - f) + fog * f; }
  static Sample level_sample(const hls::UInt<8>& c) { return double(c.value()); }
};

}  // namespace cig
