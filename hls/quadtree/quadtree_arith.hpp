// Parameter arithmetic of the recursive-subdivision raster processor, as a policy: the setup, the
// PE and the pixel processor (hls/quadtree) are templates over it. QuadFixedArith<Fmt> is the
// bit-accurate hardware arithmetic in the formats Fmt names (records.hpp); the C model plugs a
// double policy (cmodel/quadtree/quadtree_double_arith.hpp) into the same templates to get each
// kernel's twin. Coverage (edge functions, d, masks) is exact integer arithmetic in both: there is
// nothing to quantize in it once the formatter has placed the vertices on its grid.
//
// A policy provides
//   VertexI, VertexZ   a vertex's intensity and depth as the setup reads them
//   Value              a vertex parameter value in value units (records.hpp)
//   Gradient, Param    D, E and plane values F, f
//   Sample, Accum      a sample's colour component; a pixel's sum of 16 of them
// and the operations below.
#pragma once

// hls-subset-helper: the arithmetic policy shared by the quadtree setup, PE and pixel processor.

#include "hls/pixel/sample_colour.hpp"
#include "hls/quadtree/records.hpp"
#include "hls/types/zfloat_ops.hpp"

CIG_HLS_BEGIN_NAMESPACE

// Newell sums of a polygon's parameter (setup): the plane v = a hx + b hy + c that the polygon's
// vertices (hx_k, hy_k, v_k) define, as the area-weighted mean normal (exact for planar values,
// e.g. every triangle and 1/Z of every planar polygon; the best planar fit of Gouraud intensities
// that are not planar):
//   nx = sum (hy_k - hy_k+1)(v_k + v_k+1),  ny = sum (v_k - v_k+1)(hx_k + hx_k+1),
//   nz = sum (hx_k - hx_k+1)(hy_k + hy_k+1)  (twice the signed area),  a = -nx/nz, b = -ny/nz;
// the offset makes the plane's mean residual over the vertices zero.
// Integer inputs: hx, hy half units (0..8190); sample coordinates of vertex k in 1/128 samples,
// i7_k = (hx_k - o) * 2^(7 - log2 s) (exact: s = 2^(11 - n) divides 128), summed: si7, sj7.

template <class Fmt>
struct QuadFixedArith {
  using Format = Fmt;
  static constexpr int G = Fmt::G;
  static constexpr int MW = Fmt::MW;
  static constexpr int V = Fmt::V;
  using VertexI = UInt<8>;
  using VertexZ = ZFloat;
  using Value = Int<V + 1>;                   // vertex value, value units: I 0..255, W 0..2^MW
  using Gradient = Int<Fmt::kGradientWidth>;  // D, E: G fractional bits, |.| < 2^V
  using Param = Int<Fmt::kParamWidth>;        // F, f: G fractional bits
  using NewellSum = Int<V + 19>;              // |nx|, |ny| < 8 * 2^13 * 2^(V + 1) = 2^(V + 17)
  using Sample = SampleColour;
  using Accum = UFixed<20, 12>;  // a pixel's 16 samples summed: exact
  using FogTable = ::cig::hls::FogTable;
  using FogFactorType = FogFactor;

  static Value intensity_value(const VertexI& i) { return Value(i.value()); }
  // The per-polygon block exponent of W: every vertex's 1/Z is scaled by 2^(MW + e_min - 127)
  // (e_min: the smallest e8m7 exponent of the polygon's depths, i.e. its nearest binade), so the
  // nearest vertex gets a value in (2^(MW-1), 2^MW]. 1/Z = value * 2^w_exponent.
  static int w_exponent(int e_min) { return 127 - MW - e_min; }
  // W of a vertex: 2^(MW + 7 + e_min - e) / significand, rounded half up (one divider per vertex);
  // vertices more than MW + 8 binades behind the nearest get 0 (below half a value unit).
  static Value inverse_depth_value(const VertexZ& z, int e_min) {
    const int sh = MW + 7 + e_min - int(z.exponent().value());
    if (sh < 0) return Value(0);
    const Int<29> one = Int<29>(std::int64_t{1}) << sh;  // sh <= MW + 7 <= 27
    const UFixed<V, V, Quant::kRound, Overflow::kSat> q = fixed_div<UFixed<V, V, Quant::kRound, Overflow::kSat>>(
        Fixed<29, 29>::from_raw(one), UFixed<8, 8>::from_raw(z.significand()));
    return Value(q.raw().value());
  }
  using SumValue = Int<V + 5>;  // sum of up to 8 vertex values
  static int depth_exponent(const VertexZ& z) { return int(z.exponent().value()); }
  // nx term (hy_k - hy_k+1)(v_k + v_k+1) and ny term (v_k - v_k+1)(hx_k + hx_k+1), exact:
  // |dhy| < 2^13, |hx_k + hx_k+1| < 2^14, |v| <= 2^(V-1) for W and < 2^8 for I.
  static NewellSum newell_x(const Int<15>& dhy, const Value& v0, const Value& v1) { return NewellSum(dhy * (v0 + v1)); }
  static NewellSum newell_y(const Int<15>& shx, const Value& v0, const Value& v1) { return NewellSum(shx * (v0 - v1)); }
  static NewellSum newell_add(const NewellSum& a, const NewellSum& t) { return wrap<V + 19>(a + t); }
  static SumValue value_add(const SumValue& a, const Value& v) { return wrap<V + 5>(a + v); }

  // The plane in sample units: D = a s, E = b s (s = 2^ls), rounded half up to G fractional bits
  // and saturated to |.| < 2^V; F, the value at sample (0, 0), from the ROUNDED gradients so that
  // the mean residual over the vertices is at most half an LSB: F = round((sum v - D si - E sj) /
  // n). nz != 0 (the caller drops zero-area pieces).
  static void plane(const NewellSum& nx, const NewellSum& ny, const Int<34>& nz, const SumValue& sum_v,
                    const Int<24>& si7, const Int<24>& sj7, int n, int ls, Gradient& d_out, Gradient& e_out,
                    Param& f_out) {
    using GradientFormat = Fixed<Fmt::kGradientWidth, Fmt::kGradientWidth - G, Quant::kRound, Overflow::kSat>;
    const Int<V + 26> nxs = Int<V + 26>(-(nx.value()) * (std::int64_t{1} << ls));  // -nx s, exact
    const Int<V + 26> nys = Int<V + 26>(-(ny.value()) * (std::int64_t{1} << ls));
    const GradientFormat dg =
        fixed_div<GradientFormat>(Fixed<V + 26, V + 26>::from_raw(nxs), Fixed<34, 34>::from_raw(nz));
    const GradientFormat eg =
        fixed_div<GradientFormat>(Fixed<V + 26, V + 26>::from_raw(nys), Fixed<34, 34>::from_raw(nz));
    d_out = dg.raw();
    e_out = eg.raw();
    // numerator in units of 2^-(G + 7): sum v * 2^(G + 7) - D_raw si7 - E_raw sj7 (exact).
    const Int<V + 12 + G> sv = shl<G + 7>(sum_v);
    const Int<63> num = Int<63>(sv.value() - d_out.value() * si7.value() - e_out.value() * sj7.value());
    using OffsetFormat = Fixed<Fmt::kParamWidth, Fmt::kParamWidth - G, Quant::kRound, Overflow::kSat>;
    const OffsetFormat f =
        fixed_div<OffsetFormat>(Fixed<63, 63 - G - 7>::from_raw(num), Fixed<5, 5>::from_raw(Int<5>(n)));
    f_out = f.raw();
  }

  // The parameter recurrence of seed 004: f + 2^k D (and likewise E), exact. With k <= 12 the
  // shifted gradient has V + 13 + G bits, below the parameter's V + 16 + G.
  static Param step(const Param& f, const Gradient& g, int k) { return wrap<Fmt::kParamWidth>(f + (Param(g) << k)); }
  // The value at sample (di, dj) of a pixel whose top-left sample has value f (the pixel
  // processor's 16 sample lanes), exact.
  static Param at_sample(const Param& f, const Gradient& d, const Gradient& e, int di, int dj) {
    return wrap<Fmt::kParamWidth>(f + d * Int<3>(di) + e * Int<3>(dj));
  }

  // ---- Pixel processor ----
  // I of a sample: the value rounded half up to its 8 integer bits plus G fractional bits, i.e.
  // exactly, then saturated to [0, 256 - 2^-G] (a plane may leave the vertex range inside the
  // polygon only for non-planar Gouraud values; outside it, by extrapolation, never in a covered
  // sample of a triangle).
  using Intensity = UFixed<8 + G, 8, Quant::kRound, Overflow::kSat>;
  static Intensity intensity(const Param& v) {
    return Intensity(Fixed<Fmt::kParamWidth, Fmt::kParamWidth - G>::from_raw(v));
  }
  // The e8m7 code of 1/Z = v * 2^(w_exponent - G) (nearest, ties to even; v <= 0, which only
  // extrapolation beyond the horizon produces, gives the smallest code: infinitely far).
  static ZFloat inverse_depth_code(const Param& v, const Int<10>& w_exponent) {
    const std::int64_t raw = v.value();
    const std::int64_t s = raw >= (std::int64_t{1} << 41) ? (std::int64_t{1} << 41) - 1 : raw;
    return zfloat_from_aligned(int(w_exponent.value()) - G + 127 + 7 + kZGuardBits, Int<42>(s));
  }
  // A covered sample's colour component: colour x I, then fog by 1/Z through the fog table (whose
  // host fill reads the code as 1/Z).
  static Sample sample_colour(const SampleLevel& c, const Intensity& i, const FogFactor& f, const SampleLevel& fog) {
    return fog_mix(shade(c, i), fog, f);
  }
  static FogFactor fog_factor(const FogTable& t, const Param& v, const Int<10>& w_exponent) {
    return fog_lookup(t, inverse_depth_code(v, w_exponent));
  }
  static Sample level_sample(const SampleLevel& c) { return ::cig::hls::level_sample(c); }
  static Accum accumulate(const Accum& a, const Sample& s) { return Accum(a + s); }
  // The box filter: the mean of the 16 samples, rounded half up, saturated (= resolve_box).
  static UInt<8> resolve(const Accum& sum) {
    const UFixed<8, 8, Quant::kRound, Overflow::kSat> mean(UFixed<20, 8>::from_raw(sum.raw()));
    return mean.raw();
  }
};

using DefaultQuadArith = QuadFixedArith<QuadFormatDefault>;

CIG_HLS_END_NAMESPACE
