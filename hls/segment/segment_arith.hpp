// Arithmetic of the segment processor, as a policy: every kernel of hls/segment is a template
// over it. FixedSegmentArith<Fmt> is the bit-accurate hardware arithmetic in the formats Fmt
// names; the C model instantiates the same kernels with a double policy (cmodel/segment/
// double_arith.hpp) to get each kernel's double-precision twin: the same algorithm, no
// quantization.
//
// A policy provides the value types
//   Coord      formatted X, Y (grid units)       fixed: UInt<12>         (eq. 1)
//   Level      formatted I (0..255)               fixed: UInt<8>
//   Depth      formatted Z                        fixed: ZFloat (e8m7)
//   X          an edge's X at a sample row         Fmt::X
//   Slope      X change per sample row (eq. 2)     Fmt::Slope
//   Intensity  I at a segment end (eq. 3)          Fmt::Intensity
// and the operations the kernels need (below). Integer quantities (rows, lines, counts, codes)
// are plain ints in every policy: they are decisions, not values to quantize.
#pragma once

// hls-subset-helper: the arithmetic policy and format sets shared by every segment kernel.

#include "hls/pixel/attribute_planes.hpp"
#include "hls/segment/records.hpp"
#include "hls/types/zfloat_ops.hpp"

CIG_HLS_BEGIN_NAMESPACE

template <class Fmt>
struct FixedSegmentArith {
  using Format = Fmt;
  using Coord = UInt<12>;
  using Diameter = UInt<3>;
  using Level = UInt<8>;
  using VertexIntensity = UInt<9>;  // 256 Is, 0..256 (the formatter's I)
  using Depth = ZFloat;
  using Area = Int<32>;  // twice the area, grid units^2: |.| <= 16 * 4095 * 8190 < 2^30
  using X = typename Fmt::X;
  using Slope = typename Fmt::Slope;
  using Intensity = typename Fmt::Intensity;

  static int coord_half(const Coord& c) { return int(c.value()) * 2; }

  // Perspective-correct mode: the polygon's planes of I and W = 1/Z, in the pixel stages' shared
  // format (hls/pixel/attribute_planes.hpp), fitted as the quadtree setup fits them.
  using Plane = PlaneFixedArith<PlaneFormatDefault>;
  using Planes = AttributePlanes<Plane>;
  // The video channel's row sharing (hls/segment/video_channel.hpp, RowShade). The e8m7 code of W
  // is monotone in W, so the samples between w0 and w1 have codes between theirs: the same fog
  // factor when the table holds one value over that range (a range of up to kFogScan codes is
  // read; a longer one counts as not shared). I is flat along a row when D_I = 0.
  static constexpr int kFogScan = 32;
  static bool same_fog(const typename Plane::FogTable& t, const typename Plane::Param& w0,
                       const typename Plane::Param& w1, const Int<10>& w_exponent) {
    const int c0 = int(Plane::inverse_depth_code(w0, w_exponent).bits.value());
    const int c1 = int(Plane::inverse_depth_code(w1, w_exponent).bits.value());
    const int lo = c0 < c1 ? c0 : c1, hi = c0 < c1 ? c1 : c0;
    if (hi - lo > kFogScan) return false;
    for (int k = 1; k <= kFogScan; ++k) {
      if (lo + k > hi) break;
      if (t.f[lo + k].raw().value() != t.f[lo].raw().value()) return false;
    }
    return true;
  }
  static bool is_flat(const typename Plane::Gradient& d) { return d.value() == 0; }
  // The fog factor steps (256 levels over the fog range): a word of a row in fog often holds one.
  static constexpr int kWordFogSpan = 8;
  // No fog: fog_mix(s, fog, 0) = s exactly (s * 256 / 256 + 0), colour x I alone.
  static bool no_fog(const typename Plane::FogFactorType& f) { return f.raw().value() == 0; }

  // Over the polygon's vertices without consecutive repeats (fan_triangle false: a convex polygon),
  // or on its fan triangle (0, k, k + 1) of largest area (a polygon that snapping made non-convex:
  // every span piece gets the same planes). A polygon of no area gets zero planes (it draws
  // nothing).
  static void fit_planes(const FormattedPrimitive& in, int raster_log2, bool fan_triangle, Planes& out,
                         int side_log2 = kDefaultSideLog2) {
    int hx[kMaxVertices], hy[kMaxVertices], idx[kMaxVertices];
    typename Plane::VertexI vi[kMaxVertices];
    typename Plane::VertexZ vz[kMaxVertices];
    const int n = int(in.n.value());
    for (int k = 0; k < kMaxVertices; ++k) {
      hx[k] = 2 * int(in.v[k].x.value());
      hy[k] = 2 * int(in.v[k].y.value());
      vi[k] = typename Plane::VertexI(in.v[k].i.value());
      vz[k] = in.v[k].z;
      idx[k] = 0;
    }
    const int m = fan_triangle ? fan_triangle_vertices(hx, hy, n, idx) : distinct_vertices(hx, hy, n, idx);
    int e_min = 255;
    for (int k = 0; k < kMaxVertices; ++k) {
      if (k >= (fan_triangle ? n : m)) break;
      const int e = Plane::depth_exponent(vz[fan_triangle ? k : idx[k]]);
      if (e < e_min) e_min = e;
    }
    Int<34> nz(0);
    for (int k = 0; k < kMaxVertices; ++k) {
      if (k >= m) break;
      const int a = idx[k], b = idx[k + 1 == m ? 0 : k + 1];
      nz = wrap<34>(nz + Int<15>(hx[a] - hx[b]) * Int<15>(hy[a] + hy[b]));
    }
    out = Planes();
    if (m < 3 || nz.value() == 0) return;
    fit_attribute_planes<Plane>(vi, vz, hx, hy, idx, m, nz, raster_log2, e_min, out, side_log2);
  }
  // The vertices without consecutive (and closing) repeats, as the quadtree setup keeps them.
  static int distinct_vertices(const int (&hx)[kMaxVertices], const int (&hy)[kMaxVertices], int n,
                               int (&idx)[kMaxVertices]) {
    int m = 0;
    for (int k = 0; k < kMaxVertices; ++k) {
      if (k >= n) break;
      if (m > 0 && hx[k] == hx[idx[m - 1]] && hy[k] == hy[idx[m - 1]]) continue;
      idx[m++] = k;
    }
    for (int k = 0; k < kMaxVertices; ++k) {
      if (m <= 1 || !(hx[idx[m - 1]] == hx[idx[0]] && hy[idx[m - 1]] == hy[idx[0]])) break;
      --m;
    }
    return m;
  }
  // The fan triangle (0, k, k + 1) of largest area as a vertex cycle; 0 vertices if none.
  static int fan_triangle_vertices(const int (&hx)[kMaxVertices], const int (&hy)[kMaxVertices], int n,
                                   int (&idx)[kMaxVertices]) {
    const int best = ::cig::hls::largest_fan_triangle(hx, hy, n);
    if (best == 0) return 0;
    idx[0] = 0;
    idx[1] = best;
    idx[2] = best + 1;
    return 3;
  }

  // Eq. 5-6: dY_j * sX_j = (Y_{j+1} - Y_j) * (X_{j+1} + X_j); twice the area is minus their sum.
  static Area area_term(const Coord& x0, const Coord& y0, const Coord& x1, const Coord& y1) {
    return Area((y1 - y0) * (x1 + x0));  // Int<13> * UInt<13> -> Int<27>, exact
  }
  static Area area_sub(const Area& a, const Area& t) { return wrap<32>(a - t); }
  static bool is_zero(const Area& a) { return a.value() == 0; }
  static bool is_positive(const Area& a) { return a.value() > 0; }
  // Area code (eq. 6 bucket): one code per octave of area, smaller codes for larger polygons:
  // area = |twice| / 2 units^2; code = clamp(20 - floor(log2(area)), 1, 15), so code 15 holds
  // polygons under 64 units^2 (one pixel at N = 512) and code 1 those of 2^19 units^2 and more.
  static int area_code(const Area& twice) {
    const UInt<32> mag = UInt<32>(twice.value() < 0 ? -twice.value() : twice.value());
    const int msb = leading_one(mag);  // floor(log2(twice)); the area's is one less
    const int code = 21 - msb;         // 20 - (msb - 1)
    return code < 1 ? 1 : code > 15 ? 15 : code;
  }
  // Ceiling and floor in half units are exact for integer grid coordinates.
  static int first_row_at_or_after(const LatticeGeometry& g, const Coord& y) {
    return g.first_sample_at_or_after_half(coord_half(y));
  }

  // Eq. 2 per sample row: (xb - xa) / (yb - ya) * row spacing, rounded to Slope.
  // Row spacing is 2^s half units = 2^(s-1) grid units; the quotient is taken on half units.
  static Slope slope_per_row(const LatticeGeometry& g, const Coord& xa, const Coord& ya, const Coord& xb,
                             const Coord& yb) {
    const Int<14> dx = Int<14>(int(xb.value()) - int(xa.value()));
    const Int<14> dy2 = Int<14>(2 * (int(yb.value()) - int(ya.value())));  // half units, > 0
    const Int<26> num = Int<26>(dx.value() * (1 << g.log2_half_spacing));  // dx * spacing (half units)
    return fixed_div<Slope>(Fixed<26, 26>::from_raw(num), Fixed<14, 14>::from_raw(dy2));
  }
  // The preprocessor's crossing: X at row k on edge (xa, ya)-(xb, yb), one rounding (eq. 2 at a
  // point). It loads the X accumulator of the incremental stepping, so it is held in the slope's
  // format (the accumulator's fractional bits), not rounded to X: with X's precision its rounding
  // error (up to 1/2 LSB_X) would add to the stepping's before the final rounding into X, and an
  // exact crossing on a sample column could then round off it (see SegmentFormatFine).
  static Slope crossing(const LatticeGeometry& g, const Coord& xa, const Coord& ya, const Coord& xb, const Coord& yb,
                        int k) {
    const Int<14> dx = Int<14>(int(xb.value()) - int(xa.value()));
    const Int<14> dy2 = Int<14>(2 * (int(yb.value()) - int(ya.value())));
    const Int<15> t2 = Int<15>(g.sample_half(k) - coord_half(ya));  // row's distance below ya, half units
    const Int<29> num = dx * t2;
    const Slope along = fixed_div<Slope>(Fixed<29, 29>::from_raw(num), Fixed<14, 14>::from_raw(dy2));
    return Slope(Fixed<13, 13>::from_raw(Int<13>(int(xa.value()))) + along);
  }
  // Incremental stepping: x + rows * slope from the accumulator (the first crossing, in the
  // slope's format), rounded to X (the accumulator is exact in hardware; rounding happens when
  // the value leaves it).
  static X step(const Slope& x, const Slope& s, int rows) { return X(x + Fixed<13, 13>::from_raw(Int<13>(rows)) * s); }
  // Linear interpolation x0 + (x1 - x0) * num / den (den in 1..7: a line's rows, S <= 8).
  static X lerp_x(const X& x0, const X& x1, int num, int den) {
    const auto diff = x1 - x0;
    const auto scaled = diff * Fixed<4, 4>::from_raw(Int<4>(num));
    return X(x0 + fixed_div<X>(scaled, Fixed<4, 4>::from_raw(Int<4>(den))));
  }

  // Where on the edge eq. 3-4 are evaluated: yt (quarter units) below yb, clamped to the edge
  // [0, 4 (ye - yb)]. The edge that holds a segment's middle row can end inside the line; without
  // the clamp I and Z would extrapolate past its end (t up to 16 on sub-row edges).
  static int along_edge_quarter(const Coord& yb, const Coord& ye, int yt_quarter) {
    const int t4 = yt_quarter - 4 * int(yb.value()), dy4 = 4 * (int(ye.value()) - int(yb.value()));
    return t4 < 0 ? 0 : (t4 > dy4 ? dy4 : t4);
  }
  // Eq. 3: I at yt (quarter units) on an edge from (yb, ib) to (ye, ie), within [0, 256].
  static Intensity intensity_at(const VertexIntensity& ib, const VertexIntensity& ie, const Coord& yb, const Coord& ye,
                                int yt_quarter) {
    const Int<10> di = Int<10>(int(ie.value()) - int(ib.value()));
    const Int<16> t4 = Int<16>(along_edge_quarter(yb, ye, yt_quarter));  // quarter units below yb
    const Int<15> dy4 = Int<15>(4 * (int(ye.value()) - int(yb.value())));
    const Int<26> num = di * t4;
    const auto along = fixed_div<Fixed<Intensity::width + 1, 10, Intensity::quant, Overflow::kSat>>(
        Fixed<26, 26>::from_raw(num), Fixed<15, 15>::from_raw(dy4));
    return Intensity(Fixed<10, 10>::from_raw(Int<10>(int(ib.value()))) + along);  // between ib and ie
  }
  // Eq. 4 on e8m7 values.
  static Depth depth_at(const Depth& zb, const Depth& ze, const Coord& yb, const Coord& ye, int yt_quarter) {
    return zfloat_lerp(zb, ze, Int<16>(along_edge_quarter(yb, ye, yt_quarter)),
                       Int<16>(4 * (int(ye.value()) - int(yb.value()))));
  }

  // ---- Video channel ----
  // Sample colour, fog and the box filter are shared with every engine (hls/pixel/sample_colour.hpp).
  using Sample = SampleColour;
  using FogFactor = ::cig::hls::FogFactor;
  using FogTable = ::cig::hls::FogTable;

  // X of sample column i: 2 X_i = (u/2) i + u/4 - 2 (half units), exact with one fractional bit.
  static X column_x(const LatticeGeometry& g, int i) { return X(Fixed<16, 15>::from_raw(Int<16>(g.sample_half(i)))); }
  static X midpoint(const X& a, const X& b) {
    const auto sum = a + b;                                                                   // one more integer bit
    return X(Fixed<decltype(sum)::width, decltype(sum)::int_bits - 1>::from_raw(sum.raw()));  // halve
  }
  // Interpolation along a segment: t = (x - x_left) / span through one reciprocal per segment
  // (a divider per segment, a multiplier per sample, as a pipelined video channel does).
  using Reciprocal = UFixed<32, 8, Quant::kRound, Overflow::kSat>;  // 1/span, 24 fractional bits
  using Ratio = UFixed<17, 1, Quant::kRound, Overflow::kSat>;       // t in [0, 1], 16 fractional bits
  static Reciprocal reciprocal(const X& span) {
    if (!(span.raw().value() > 0)) return Reciprocal();  // empty span: t = 0, the left end's values
    return fixed_div<Reciprocal>(Fixed<2, 2>::from_raw(Int<2>(1)), span);
  }
  static Ratio ratio(const X& along, const Reciprocal& inv) {
    if (!(along.raw().value() > 0)) return Ratio();
    const Ratio t(along * to_signed(inv));  // Fixed<W, 14> * Fixed<33, 9>: exact, then rounded
    return t.raw().value() > (1u << 16) ? Ratio::from_raw_value(1u << 16) : t;
  }
  static Intensity lerp_intensity(const Intensity& il, const Intensity& ir, const Ratio& t) {
    return Intensity(to_signed(il) + (ir - il) * to_signed(t));
  }
  static Depth lerp_depth(const Depth& zl, const Depth& zr, const Ratio& t) { return zfloat_lerp_ratio(zl, zr, t); }
  static FogFactor fog_factor(const FogTable& t, const Depth& z) { return fog_lookup(t, z); }
  template <class I>  // I at a segment end (Intensity) or from the plane (Plane::Intensity)
  static Sample shade(const Level& c, const I& i) {
    return ::cig::hls::shade(c, i);
  }
  static Sample mix(const Sample& s, const Level& fog, const FogFactor& f) { return fog_mix(s, fog, f); }
  static Sample level_sample(const Level& c) { return ::cig::hls::level_sample(c); }
  static UInt<8> resolve(const Sample (&s)[kMaxSamplesPerPixel], int side_log2) { return resolve_box(s, side_log2); }
  // The same box filter fed a sample at a time (the video channel's accumulator): resolve_box.
  using BoxAccum = BoxSum;
  static BoxAccum box_add(const BoxAccum& sum, const Sample& s) { return BoxAccum(sum + s); }
  static UInt<8> resolve_sum(const BoxAccum& sum, int side_log2) { return resolve_box_sum(sum, side_log2); }

  // The video channel's sample columns: first column i with X_i >= x, and first with X_i >= x
  // (exclusive end for a right edge), where 2 X_i = (u/2) i + u/4 - 2 (half units).
  static int first_column_at_or_after(const LatticeGeometry& g, const X& x) {
    // ceil((2x - offset) / 2^s), computed on x's raw value (F fractional bits).
    constexpr int F = X::frac_bits;
    const Int<X::width + 9> t = shl<1>(x.raw()) - (Int<X::width + 7>(g.offset_half) << F);
    const int sh = F + g.log2_half_spacing;
    const Int<X::width + 9> bias((1 << sh) - 1);
    return int(t.value() <= 0 ? -((-t) >> sh).value() : ((t + bias) >> sh).value());
  }
};

// Format sets for the run-time / error table. X: grid units; Slope: grid units per sample row;
// Intensity: 0..256. All round to nearest (half up) and saturate.
struct SegmentFormatCoarse {
  static constexpr const char* name = "x2s6i0";
  using X = Fixed<16, 14, Quant::kRound, Overflow::kSat>;
  using Slope = Fixed<26, 20, Quant::kRound, Overflow::kSat>;
  using Intensity = UFixed<9, 9, Quant::kRound, Overflow::kSat>;
};
struct SegmentFormatMedium {
  static constexpr const char* name = "x4s10i2";
  using X = Fixed<18, 14, Quant::kRound, Overflow::kSat>;
  using Slope = Fixed<30, 20, Quant::kRound, Overflow::kSat>;
  using Intensity = UFixed<11, 9, Quant::kRound, Overflow::kSat>;
};
// Fine: the coverage is EXACT (equal, sample for sample, to the exact edge functions with the tie
// rule). An edge's exact crossing at a sample row, xa + dx (Y_k - ya) / dy, and a sample column
// X_i (a multiple of 1/2 unit) differ by a multiple of 1/(2 dy) >= 1/8190 > 2^-13 units, or are
// equal. The accumulator holds the first crossing and the slope rounded to 26 fractional bits
// (errors <= 2^-27 each), so after m <= 4095 steps it is off by at most (m + 1) 2^-27 <= 2^-15,
// less than LSB_X / 2 = 2^-14: a crossing ON a column rounds to it exactly, any other ends within
// 2^-14 + 2^-15 < 2^-13 of its exact value, on the same side of every column. So the video
// channel's decisions (left X <= X_i < right X) are the exact ones at every raster 16..1024.
// (With 10 / 18 fractional bits, crossings within 2^-11 of a column were rounded onto it.)
struct SegmentFormatFine {
  static constexpr const char* name = "x13s26i6";
  using X = Fixed<27, 14, Quant::kRound, Overflow::kSat>;
  using Slope = Fixed<46, 20, Quant::kRound, Overflow::kSat>;
  using Intensity = UFixed<15, 9, Quant::kRound, Overflow::kSat>;
};

// The format of the top functions and of `--engine segment` unless told otherwise.
using SegmentFormatDefault = SegmentFormatFine;
using DefaultSegmentArith = FixedSegmentArith<SegmentFormatDefault>;

CIG_HLS_END_NAMESPACE
