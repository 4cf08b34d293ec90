// The double-precision twin of the segment processor's arithmetic: the policy that, plugged into
// the hls/segment kernels, turns each of them into its twin (the same algorithm, no
// quantization). Values keep the fixed policy's units: grid units for X and Y, 0..255 for levels,
// metres for Z, output LSB for samples. Integer decisions (rows, columns, area codes) follow the
// same rules on the unrounded values.
#pragma once

#include <algorithm>
#include <cmath>

#include "hls/segment/segment_arith.hpp"
#include "pixel/plane_double_arith.hpp"

namespace cig {

struct DoubleSegmentArith {
  using LatticeGeometry = hls::LatticeGeometry;
  using Coord = double;
  using Diameter = double;
  using Level = double;
  using VertexIntensity = double;
  using Depth = double;
  using Area = double;
  using X = double;
  using Slope = double;
  using Intensity = double;
  using Sample = double;
  using FogFactor = double;
  struct FogTable {
    double start = 1e30, end = 2e30;
  };

  // Perspective-correct mode: the planes of I and W = 1/Z through the unsnapped vertices, in
  // sample units (Newell's area-weighted fit, as the fixed kernel; the twin never splits a polygon,
  // so fan_triangle does not arise).
  using Plane = PlaneDoubleArith;
  using Planes = hls::AttributePlanes<Plane>;
  static void fit_planes(const hls::FormattedPrimitiveT<DoubleSegmentArith>& in, int raster_log2, bool, Planes& out,
                         int side_log2 = hls::kDefaultSideLog2) {
    const LatticeGeometry g = LatticeGeometry::for_raster(raster_log2, side_log2);
    const double s = std::ldexp(1.0, g.log2_half_spacing), o = g.offset_half;
    const int n = int(in.n.value());
    double nz = 0, sx = 0, sy = 0, nx[2] = {0, 0}, ny[2] = {0, 0}, sv[2] = {0, 0};
    auto value = [&](int k, int p) { return p == hls::kParamIntensity ? in.v[k].i : 1.0 / in.v[k].z; };
    for (int k = 0; k < n; ++k) {
      const int k1 = k + 1 == n ? 0 : k + 1;
      const double x0 = (2 * in.v[k].x - o) / s, y0 = (2 * in.v[k].y - o) / s;
      const double x1 = (2 * in.v[k1].x - o) / s, y1 = (2 * in.v[k1].y - o) / s;
      nz += (x0 - x1) * (y0 + y1);
      sx += x0;
      sy += y0;
      for (int p = 0; p < hls::kPlaneParams; ++p) {
        nx[p] += (y0 - y1) * (value(k, p) + value(k1, p));
        ny[p] += (value(k, p) - value(k1, p)) * (x0 + x1);
        sv[p] += value(k, p);
      }
    }
    out = Planes();
    if (n < 3 || nz == 0) return;
    for (int p = 0; p < hls::kPlaneParams; ++p) {
      out.d[p] = -nx[p] / nz;
      out.e[p] = -ny[p] / nz;
      out.f[p] = (sv[p] - out.d[p] * sx - out.e[p] * sy) / n;
    }
    out.w_exponent = hls::Int<10>(0);
  }

  // The video channel's row sharing (RowShade): for W > 0 and end > start the fog factor
  // clamp((1/W - start) / (end - start), 0, 1) is monotone in W (each rounded step is), and W along
  // a row is monotone in i, so equal factors at both ends hold between; I is flat when D_I = 0.
  static bool same_fog(const Plane::FogTable& t, double w0, double w1, const hls::Int<10>& e) {
    return w0 > 0 && w1 > 0 && t.end > t.start && Plane::fog_factor(t, w0, e) == Plane::fog_factor(t, w1, e);
  }
  static bool is_flat(double d) { return d == 0; }
  // The twin's fog factor is continuous: two samples share it only where it is clamped (0 or 1),
  // which the row's check finds; no word-level check (a span beyond a word).
  static constexpr int kWordFogSpan = 64;
  // No fog: c I / 256 (1 - 0) + fog 0 = c I / 256 exactly, colour x I alone (shade).
  static bool no_fog(double f) { return f == 0; }

  static double row_y(const LatticeGeometry& g, int k) { return 0.5 * g.sample_half(k); }
  static double spacing(const LatticeGeometry& g) { return std::ldexp(1.0, g.log2_half_spacing - 1); }
  static int first_row_at_or_after(const LatticeGeometry& g, double y) {
    return int(std::ceil((2 * y - g.offset_half) / std::ldexp(1.0, g.log2_half_spacing)));
  }
  static double area_term(double x0, double y0, double x1, double y1) { return (y1 - y0) * (x1 + x0); }
  static double area_sub(double a, double t) { return a - t; }
  static bool is_zero(double a) { return a == 0; }
  static bool is_positive(double a) { return a > 0; }
  static int area_code(double twice) {
    const double m = std::abs(twice);
    if (m < 1) return 15;
    const int msb = int(std::floor(std::log2(m)));
    return std::clamp(21 - msb, 1, 15);
  }
  static double slope_per_row(const LatticeGeometry& g, double xa, double ya, double xb, double yb) {
    return (xb - xa) / (yb - ya) * spacing(g);
  }
  static double crossing(const LatticeGeometry& g, double xa, double ya, double xb, double yb, int k) {
    return xa + (row_y(g, k) - ya) * (xb - xa) / (yb - ya);
  }
  static double step(double x, double s, int rows) { return x + rows * s; }
  static double lerp_x(double x0, double x1, int num, int den) { return x0 + (x1 - x0) * num / den; }
  // t clamped to the edge, as the fixed-point intensity_at/depth_at.
  static double along_edge(double yb, double ye, int yt_quarter) {
    return std::clamp(0.25 * yt_quarter - yb, 0.0, ye - yb);
  }
  static double intensity_at(double ib, double ie, double yb, double ye, int yt_quarter) {
    return std::clamp(ib + (ie - ib) * along_edge(yb, ye, yt_quarter) / (ye - yb), 0.0, 255.0);
  }
  static double depth_at(double zb, double ze, double yb, double ye, int yt_quarter) {
    return std::max(1e-30, zb + (ze - zb) * along_edge(yb, ye, yt_quarter) / (ye - yb));
  }
  static double column_x(const LatticeGeometry& g, int i) { return 0.5 * g.sample_half(i); }
  static double midpoint(double a, double b) { return 0.5 * (a + b); }
  using Reciprocal = double;
  using Ratio = double;
  static double reciprocal(double span) { return span > 0 ? 1.0 / span : 0.0; }
  static double ratio(double along, double inv) { return along > 0 ? std::min(1.0, along * inv) : 0.0; }
  static double lerp_intensity(double il, double ir, double t) { return il + (ir - il) * t; }
  static double lerp_depth(double zl, double zr, double t) { return zl + (zr - zl) * t; }
  static double fog_factor(const FogTable& t, double z) {
    return std::clamp((z - t.start) / (t.end - t.start), 0.0, 1.0);
  }
  static double shade(double c, double i) { return c * i / 256.0; }
  static double mix(double s, double fog, double f) { return s * (1 - f) + fog * f; }
  static double level_sample(double c) { return c; }
  static hls::UInt<8> resolve(const double (&s)[hls::kMaxSamplesPerPixel], int side_log2) {
    double sum = 0;
    for (int k = 0; k < 1 << (2 * side_log2); ++k) sum = box_add(sum, s[k]);
    return resolve_sum(sum, side_log2);
  }
  // The same mean fed a sample at a time, in the same order.
  using BoxAccum = double;
  static double box_add(double sum, double s) { return sum + s; }
  static hls::UInt<8> resolve_sum(double sum, int side_log2) { return PlaneDoubleArith::box_mean(sum, side_log2); }
  static int first_column_at_or_after(const LatticeGeometry& g, double x) {
    return int(std::ceil((2 * x - g.offset_half) / std::ldexp(1.0, g.log2_half_spacing)));
  }
};

}  // namespace cig
