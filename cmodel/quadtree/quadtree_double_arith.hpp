// The double-precision twin of the quadtree raster processor's parameter arithmetic: plugged into
// the hls/quadtree kernels (setup, PE, pixel processor), it turns each of them into its twin: the
// same algorithm with no quantization of the planes, the parameter values, the fog or the colour.
// Coverage stays the kernels' exact integer arithmetic on the formatter's grid (there is nothing
// to quantize in it); the twin reads the unquantized vertex values (256 Is, Zs) of the formatter
// twin (cmodel/formatter/formatter_twin.hpp), so it also shows what the formatter's 8-bit I and e8m7
// Z cost. Value units as in the fixed policy, except W: the twin's W is 1/Z itself (w_exponent 0).
#pragma once

#include <algorithm>
#include <cmath>

#include "hls/quadtree/records.hpp"

namespace cig {

struct QuadDoubleArith {
  using VertexI = double;  // 256 Is, clamped to [0, 255] (the formatter twin)
  using VertexZ = double;  // Zs
  using Value = double;
  using Gradient = double;
  using Param = double;
  using NewellSum = double;
  using SumValue = double;
  using Sample = double;
  using Accum = double;
  using Intensity = double;
  using FogFactorType = double;
  struct FogTable {
    double start = 1e30, end = 2e30;
  };

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
  static Param step(double f, double g, int k) { return f + std::ldexp(g, k); }
  static Param at_sample(double f, double d, double e, int di, int dj) { return f + d * di + e * dj; }
  static Intensity intensity(double v) { return std::clamp(v, 0.0, 256.0); }
  static FogFactorType fog_factor(const FogTable& t, double w, const hls::Int<10>&) {
    if (!(w > 0)) return 1.0;
    return std::clamp((1.0 / w - t.start) / (t.end - t.start), 0.0, 1.0);
  }
  static Sample sample_colour(const hls::UInt<8>& c, double i, double f, const hls::UInt<8>& fog) {
    return double(c.value()) * i / 256.0 * (1.0 - f) + double(fog.value()) * f;
  }
  static Sample level_sample(const hls::UInt<8>& c) { return double(c.value()); }
  static Accum accumulate(double a, double s) { return a + s; }
  static hls::UInt<8> resolve(double sum) { return hls::UInt<8>(int(std::lround(std::clamp(sum / 16.0, 0.0, 255.0)))); }
};

}  // namespace cig
