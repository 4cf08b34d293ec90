// Records of the formatter (SPEC C, seed 001 eq. 1): its input, the geometric processor's reals as
// IEEE-754 binary64 bit patterns, and its output, the fixed-point words every raster engine after it
// reads (the segment processor, stage D; the quadtree raster processor, stage E). Every field has
// its width here.
//
//   ScreenFrame (double) --cmodel/formatter--> RawPrimitive (binary64 bit patterns)
//     formatter_top -> FormattedPrimitive (X, Y UInt<12>, I UInt<8>, D UInt<3>, colour UInt<8>,
//                      Z e8m7)
//
// The grid and the sample lattice the formatted positions live on: sample_lattice.hpp.
#pragma once

#include "hls/formatter/sample_lattice.hpp"
#include "hls/types/fixed.hpp"
#include "hls/types/zfloat.hpp"

CIG_HLS_BEGIN_NAMESPACE

constexpr int kMaxVertices = 16;         // per polygon, after clipping (cmodel kMaxScreenVertices)
constexpr int kMaxPolygonIds = 1 << 16;  // polygons (and lights) per channel and frame: UInt<16> ids

// ---- Formatter input: the geometric processor's floating-point values -------------------------
// Every real is an IEEE-754 binary64 bit pattern (the seed's processor sends 38-bit reals; binary64
// keeps the fixed-point path equal, bit for bit, to the float reference's snapped positions).
struct RawVertex {
  UInt<64> xs, ys, zs, is;  // Xs, Ys in [-1, 1], Zs > 0, Is in [0, 1]
};

struct RawPrimitive {
  bool is_light = false;
  UInt<5> n;  // vertices (polygon: 3..16; light: the centre is v[0])
  RawVertex v[kMaxVertices];
  UInt<64> ds;         // light diameter Ds in [0, 1]
  UInt<64> colour[3];  // R, G, B in [0, 1]
  bool opaque = true, protect = false;
  UInt<16> id;  // index in the frame's polygon (or light) list
};

// ---- Formatter output (eq. 1) -----------------------------------------------------------------
// Templated on a value policy P: the formatter's own (FormatterTypes below: Coord = UInt<12>, grid
// units 0..4095; Level = UInt<8>, 0..255; Depth = ZFloat, e8m7), or an engine's double twin
// policy (cmodel/segment/double_arith.hpp), with doubles in the same units, unrounded.
template <class P>
struct FormattedVertexT {
  typename P::Coord x, y;
  typename P::VertexIntensity i;  // 256 Is, 0..256 (fixed: UInt<9>; 256 = full intensity)
  typename P::Depth z;
};

template <class P>
struct FormattedPrimitiveT {
  bool is_light = false;
  UInt<5> n;
  FormattedVertexT<P> v[kMaxVertices];
  typename P::Diameter d;       // light diameter, grid units 0..7
  typename P::Level colour[3];  // 0..255
  bool opaque = true, protect = false;
  UInt<16> id;
};

// The formatter's own output types (eq. 1 widths).
struct FormatterTypes {
  using Coord = UInt<12>;
  using Diameter = UInt<3>;
  using Level = UInt<8>;
  // I = 256 Is (eq. 1) needs 9 bits for Is = 1: with 8 bits full intensity clamped to 255 and
  // white came out 254 (255 x 255 / 256).
  using VertexIntensity = UInt<9>;
  using Depth = ZFloat;
};
using FormattedVertex = FormattedVertexT<FormatterTypes>;
using FormattedPrimitive = FormattedPrimitiveT<FormatterTypes>;

CIG_HLS_END_NAMESPACE
