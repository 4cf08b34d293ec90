// Attribute planes shared by the raster engines' pixel stages: the quadtree raster processor's
// setup and pixel processor (SPEC E) and the segment processor's preprocessor and video channel
// (SPEC D, perspective-correct mode). A polygon's intensity I and inverse depth W = 1/Z, both
// affine in screen space for a planar polygon (1/Z of a plane seen in perspective is), become two
// planes value(i, j) = D i + E j + F on the sample lattice, fitted once per polygon from the
// formatter's vertices; a sample takes exact plane values, I is saturated and W coded into the
// fog table's e8m7 address. One piece of code, so that two engines that cover the same samples of
// the same polygon produce the same sample colours.
//
// Formats (per Fmt = PlaneFormatBase<G, MW>):
//   value units  I: intensity levels 0..256 (the formatter's I, 256 Is); W: 2^-MW of the polygon's
//                largest vertex 1/Z (a block exponent per polygon, w_exponent), values 0..2^MW
//   V            = max(9, MW + 1) value bits
//   Gradient     Int<V + 1 + G>: D, E, G fractional bits, rounded half up, saturated |.| < 2^V
//                (a value swing over the whole range within one sample: only degenerate slivers)
//   Param        Int<V + 16 + G>: F and every value: anywhere on the lattice (|i|, |j| < 2^12)
//                |value| <= 2^V (1 + 2 * 2 * 2^12) < 2^(V + 14.01); sums of D i + E j are exact
#pragma once

// hls-subset-helper: the plane arithmetic shared by the quadtree and segment pixel stages.

#include "hls/formatter/records.hpp"
#include "hls/pixel/sample_colour.hpp"
#include "hls/types/zfloat_ops.hpp"

CIG_HLS_BEGIN_NAMESPACE

constexpr int kPlaneParams = 2;  // surface parameters: intensity I and inverse depth W = 1/Z
constexpr int kParamIntensity = 0;
constexpr int kParamInverseDepth = 1;

template <int kG, int kMW>
struct PlaneFormatBase {
  static constexpr int G = kG;    // fractional bits of D, E, F and every parameter value
  static constexpr int MW = kMW;  // significant bits of W = 1/Z per polygon
  static constexpr int V = (kMW + 1 > 9 ? kMW + 1 : 9);
  static constexpr int kParamWidth = V + 16 + kG;
  static constexpr int kGradientWidth = V + 1 + kG;
};

// The planes' default format (the quadtree's fine format).
struct PlaneFormatDefault : PlaneFormatBase<16, 20> {
  static constexpr const char* name = "g16w20";
};

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
struct PlaneFixedArith {
  using Format = Fmt;
  static constexpr int G = Fmt::G;
  static constexpr int MW = Fmt::MW;
  static constexpr int V = Fmt::V;
  using VertexI = UInt<9>;
  using VertexZ = ZFloat;
  using Value = Int<V + 1>;                   // vertex value, value units: I 0..256, W 0..2^MW
  using Gradient = Int<Fmt::kGradientWidth>;  // D, E: G fractional bits, |.| < 2^V
  using Param = Int<Fmt::kParamWidth>;        // F, f: G fractional bits
  using NewellSum = Int<V + 19>;              // |nx|, |ny| < 8 * 2^13 * 2^(V + 1) = 2^(V + 17)
  using SumValue = Int<V + 5>;                // sum of up to 16 vertex values
  using Sample = SampleColour;
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
  static int depth_exponent(const VertexZ& z) { return int(z.exponent().value()); }
  // nx term (hy_k - hy_k+1)(v_k + v_k+1) and ny term (v_k - v_k+1)(hx_k + hx_k+1), exact:
  // |dhy| < 2^13, |hx_k + hx_k+1| < 2^14, |v| <= 2^(V-1) for W and <= 2^8 for I.
  static NewellSum newell_x(const Int<15>& dhy, const Value& v0, const Value& v1) { return NewellSum(dhy * (v0 + v1)); }
  static NewellSum newell_y(const Int<15>& shx, const Value& v0, const Value& v1) { return NewellSum(shx * (v0 - v1)); }
  static NewellSum newell_add(const NewellSum& a, const NewellSum& t) { return wrap<V + 19>(a + t); }
  static SumValue value_add(const SumValue& a, const Value& v) { return wrap<V + 5>(a + v); }

  // The plane in sample units: D = a s, E = b s (s = 2^ls), rounded half up to G fractional bits
  // and saturated to |.| < 2^V; F, the value at sample (0, 0), from the ROUNDED gradients so that
  // the mean residual over the vertices is at most half an LSB: F = round((sum v - D si - E sj) /
  // n). nz != 0 (the caller drops zero-area pieces).
  //
  // A saturated gradient means a value swing of more than 2^V per sample, more than the whole value
  // range: a sliver of almost no area (on airfield frame 8 a terrain triangle snapped to 1 unit^2,
  // whose W plane then reached W <= 0, full fog, at its one covered sample). Such a plane is no
  // plane: it becomes flat, D = E = 0, F = round(sum v / n), the mean of the vertex values, so a
  // sample's value stays inside the vertices' range whatever the polygon's shape.
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
    if (saturated(d_out) || saturated(e_out)) {
      d_out = Gradient(0);
      e_out = Gradient(0);
    }
    // numerator in units of 2^-(G + 7): sum v * 2^(G + 7) - D_raw si7 - E_raw sj7 (exact).
    const Int<V + 12 + G> sv = shl<G + 7>(sum_v);
    const Int<63> num = Int<63>(sv.value() - d_out.value() * si7.value() - e_out.value() * sj7.value());
    using OffsetFormat = Fixed<Fmt::kParamWidth, Fmt::kParamWidth - G, Quant::kRound, Overflow::kSat>;
    const OffsetFormat f =
        fixed_div<OffsetFormat>(Fixed<63, 63 - G - 7>::from_raw(num), Fixed<5, 5>::from_raw(Int<5>(n)));
    f_out = f.raw();
  }

  static bool saturated(const Gradient& g) {
    return g.value() == Gradient::max_value || g.value() == Gradient::min_value;
  }

  // The value at sample (di, dj) from the value f at sample (0, 0) of a window or of the lattice,
  // exact (|di|, |dj| < 2^12: D di + E dj stays inside Param, see the formats above).
  static Param at_sample(const Param& f, const Gradient& d, const Gradient& e, int di, int dj) {
    return wrap<Fmt::kParamWidth>(f + d * Int<13>(di) + e * Int<13>(dj));
  }

  // I of a sample: the value rounded half up to its integer bits plus G fractional bits, i.e.
  // exactly, then saturated to [0, 256] (256 is full intensity, I = 256 Is at Is = 1: white
  // stays 255). A plane leaves the vertex range inside the polygon only for non-planar Gouraud
  // values (split into fans before this stage, cmodel/engine/fan_split.hpp) and outside it only by
  // extrapolation to a sample that snapping added.
  using Intensity = UFixed<9 + G, 9, Quant::kRound, Overflow::kSat>;
  static Intensity intensity(const Param& v) {
    const Intensity i(Fixed<Fmt::kParamWidth, Fmt::kParamWidth - G>::from_raw(v));
    const Intensity full = Intensity::from_raw_value(std::uint64_t{256} << G);
    return i.raw().value() > full.raw().value() ? full : i;
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
};

// A polygon's two planes: D, E per sample step, F at sample (0, 0) of the lattice, and W's block
// exponent.
template <class P>
struct AttributePlanes {
  typename P::Gradient d[kPlaneParams], e[kPlaneParams];
  typename P::Param f[kPlaneParams];
  Int<10> w_exponent;
};

// The fan triangle (0, k, k + 1) of largest area of an n-gon (half-unit positions): k, or 0 when
// every fan triangle is degenerate. A polygon that snapping made non-convex takes its planes from
// it (the quadtree's span-piece setup and the segment processor's edge generator alike).
inline int largest_fan_triangle(const int (&hx)[kMaxVertices], const int (&hy)[kMaxVertices], int n) {
  int best = 0;
  std::int64_t best_area = 0;
  for (int k = 1; k < kMaxVertices - 1; ++k) {
    if (k + 1 >= n) break;
    std::int64_t a =
        std::int64_t(hx[k] - hx[0]) * (hy[k + 1] - hy[0]) - std::int64_t(hy[k] - hy[0]) * (hx[k + 1] - hx[0]);
    if (a < 0) a = -a;
    if (a > best_area) {
      best_area = a;
      best = k;
    }
  }
  return best;
}

// Fits the planes of I and W through vertices idx[0..m) (half-unit positions hx, hy; values vi,
// vz; nz = twice the signed area of that vertex cycle, != 0; e_min = the polygon's nearest
// binade). f is the value at lattice sample (0, 0).
template <class P, int N>
void fit_attribute_planes(const typename P::VertexI (&vi)[kMaxVertices], const typename P::VertexZ (&vz)[kMaxVertices],
                          const int (&hx)[kMaxVertices], const int (&hy)[kMaxVertices], const int (&idx)[N], int m,
                          const Int<34>& nz, int raster_log2, int e_min, AttributePlanes<P>& out,
                          int side_log2 = kDefaultSideLog2) {
  const LatticeGeometry g = LatticeGeometry::for_raster(raster_log2, side_log2);
  const int ls = g.log2_half_spacing;  // log2 s
  const int o = g.offset_half;         // half-unit position of sample 0
  typename P::Value val[kPlaneParams][N];
  Int<24> si7(0), sj7(0);
  for (int k = 0; k < N; ++k) {
    if (k >= m) break;
    val[kParamIntensity][k] = P::intensity_value(vi[idx[k]]);
    val[kParamInverseDepth][k] = P::inverse_depth_value(vz[idx[k]], e_min);
    si7 = wrap<24>(si7 + Int<24>((hx[idx[k]] - o) * (1 << (7 - ls))));
    sj7 = wrap<24>(sj7 + Int<24>((hy[idx[k]] - o) * (1 << (7 - ls))));
  }
  for (int p = 0; p < kPlaneParams; ++p) {
    typename P::NewellSum nx = typename P::NewellSum(), ny = typename P::NewellSum();
    typename P::SumValue sum_v = typename P::SumValue();
    for (int k = 0; k < N; ++k) {
      if (k >= m) break;
      const int k1 = k + 1 == m ? 0 : k + 1;
      nx = P::newell_add(nx, P::newell_x(Int<15>(hy[idx[k]] - hy[idx[k1]]), val[p][k], val[p][k1]));
      ny = P::newell_add(ny, P::newell_y(Int<15>(hx[idx[k]] + hx[idx[k1]]), val[p][k], val[p][k1]));
      sum_v = P::value_add(sum_v, val[p][k]);
    }
    P::plane(nx, ny, nz, sum_v, si7, sj7, m, ls, out.d[p], out.e[p], out.f[p]);
  }
  out.w_exponent = Int<10>(P::w_exponent(e_min));
}

CIG_HLS_END_NAMESPACE
