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
//   Sample, Accum      a sample's colour component; a pixel's sum of its S x S samples
// and the operations below.
#pragma once

// hls-subset-helper: the arithmetic policy shared by the quadtree setup, PE and pixel processor.

#include "hls/pixel/attribute_planes.hpp"
#include "hls/quadtree/records.hpp"

CIG_HLS_BEGIN_NAMESPACE

// The plane arithmetic (Newell fit, exact sample values, intensity, 1/Z code, fog) is the pixel
// stages' shared PlaneFixedArith (hls/pixel/attribute_planes.hpp); the quadtree adds the seed's
// parameter recurrence and the pixel sum.
template <class Fmt>
struct QuadFixedArith : PlaneFixedArith<Fmt> {
  using Base = PlaneFixedArith<Fmt>;
  using typename Base::Gradient;
  using typename Base::Param;
  using typename Base::Sample;
  using Accum = BoxSum;  // a pixel's samples (up to 64) summed: exact (sample_colour.hpp)

  // The parameter recurrence of seed 004: f + 2^k D (and likewise E), exact. With k <= 12 the
  // shifted gradient has V + 13 + G bits, below the parameter's V + 16 + G.
  static Param step(const Param& f, const Gradient& g, int k) { return wrap<Fmt::kParamWidth>(f + (Param(g) << k)); }
  static Accum accumulate(const Accum& a, const Sample& s) { return Accum(a + s); }
  // The box filter: the mean of the pixel's 4^t samples, rounded half up, saturated (= resolve_box).
  static UInt<8> resolve(const Accum& sum, int side_log2) { return resolve_box_sum(sum, side_log2); }
};

using DefaultQuadArith = QuadFixedArith<QuadFormatDefault>;

CIG_HLS_END_NAMESPACE
