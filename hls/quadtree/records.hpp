// Records of the recursive-subdivision raster processor (SPEC E, seed 004): what flows from the
// setup kernel through the quadtree PEs to the pixel processor. Every field has its width here.
//
//   FormattedPrimitive (hls/formatter, eq. 1: X, Y UInt<12>, I UInt<8>, Z e8m7)
//     quadtree_setup_top   -> QuadPolygon (edge lines A i + B j + C >= 0 on the sample lattice,
//                             parameter planes D i + E j + F) and its level-0 QuadWindow
//     quadtree_pe_top      -> the covered children of one window (coverage recurrence d_i,
//                             full-coverage test, parameter recurrence f_i, mask skip), at the
//                             pixel level with their S x S-bit sample masks
//     mask memory          -> 4-bit priority masks of every window of levels 0..n-1
//     pixel processor      -> samples: colour x I, fog by 1/Z, front-to-back sub-pixel
//                             resolve; box filter
//
// Geometry. The raster has N = 2^n pixels a side (16 <= N <= 1024) and S x S samples per pixel,
// S = 2^t (t = side_log2 0..3, default 2: the seeds' 4 x 4 and the RTL's), on the formatter's
// sample lattice (hls/formatter/sample_lattice.hpp), so the lattice is SN x SN; sample (i, j) lies
// at half-unit position (s i + o, s j + o), with half units = 2 x formatter grid units,
// s = 2^(13 - n - t) and o = 2^(12 - n - t) - 2 (LatticeGeometry).
// Level l (0..n) of the subdivision splits the screen into 2^l x 2^l windows of 2^(n - l) pixels,
// i.e. 2^(n - l + t) samples a side; window (x, y) of level l has its top-left sample at
// (x, y) * 2^(n - l + t). Level n windows are pixels. Children are numbered q = 2 y_bit + x_bit
// (0 top-left, 1 top-right, 2 bottom-left, 3 bottom-right).
//
// The filter aperture of seed 004 (alpha x beta at the pixel level) is realised by the S x S point
// samples: on the SN lattice the aperture is alpha = beta = 0 (point sampling); measured in
// pixels, a window of level l spans 2^(n-l) - 1/4 pixels of sample positions, i.e. eq. 2's window
// 2^(n-l) - 1 + alpha with alpha = beta = 3/4.
#pragma once

#include "hls/formatter/records.hpp"
#include "hls/pixel/attribute_planes.hpp"

CIG_HLS_BEGIN_NAMESPACE

constexpr int kQuadMaxLevels = kMaxRasterLog2;  // levels 0..n, n = log2 N <= 10 (sample_lattice.hpp)
// Edge lines per polygon record: a PE evaluates this many edge functions in parallel. Polygons
// with more vertices are split by the setup into a fan of pieces (their shared diagonals are
// watertight under the tie rule, so the union covers exactly the polygon's samples); bounding-box
// edges (setup.hpp) are added only where slots remain.
constexpr int kQuadMaxEdges = 8;
constexpr int kQuadMaxPieces = 3;          // 16 vertices -> pieces of 8, 8 and 4 vertices
constexpr int kQuadParams = kPlaneParams;  // I and W = 1/Z (hls/pixel/attribute_planes.hpp)
constexpr int kQuadChildren = 4;

// ---- Edge functions (exact integers) ----------------------------------------------------------
// E(i, j) = A i + B j + C on the sample lattice; a sample is inside an edge when E >= 0. With
// half-unit vertex differences |dx|, |dy| <= 8190 and s <= 128: |A|, |B| <= 8190 * 128 < 2^20;
// |C| < 2 * 8190 * 8252 < 2^27.1; any window's d (the value at one lattice point, |i|, |j| < 2^12
// with |A| * SN <= 8190 * 2^13 for any lattice of SN <= 4096) lies below 2^28.2. Edge gradient: Int<22>; d: Int<32> (margin).
// The tie rule of the reference (a sample on an edge belongs to the polygon whose inward gradient
// points along +x, or +y for horizontal edges) is folded into C: an edge that does not own its
// ties has C decreased by one, so "E > 0" becomes "E - 1 >= 0" (E is an integer). Every test is
// then d >= 0.
using EdgeGradient = Int<22>;
using EdgeValue = Int<32>;

// ---- Parameter formats -------------------------------------------------------------------------
// A parameter is a plane value(i, j) = D i + E j + F in "value units" with G fractional bits, in
// the pixel stages' shared formats (hls/pixel/attribute_planes.hpp: value units, V, Param,
// Gradient). The shifted gradients of the recurrence add exactly: no rounding after the setup.
template <int kG, int kMW>
using QuadFormatBase = PlaneFormatBase<kG, kMW>;

// The formats of the run-time / error table (`cig sweep ... --vary format=coarse,medium,fine`).
struct QuadFormatCoarse : QuadFormatBase<6, 12> {
  static constexpr const char* name = "g6w12";
};
struct QuadFormatMedium : QuadFormatBase<10, 16> {
  static constexpr const char* name = "g10w16";
};
struct QuadFormatFine : QuadFormatBase<16, 20> {
  static constexpr const char* name = "g16w20";
};
using QuadFormatDefault = QuadFormatFine;

// ---- Records -------------------------------------------------------------------------------------
// Templated on the parameter arithmetic policy P (quadtree_arith.hpp): the bit-accurate policy
// has Param = Int<kParamWidth> (raw, G fractional bits) and Gradient = Int<kGradientWidth>; the C
// model's double twin has doubles in the same value units, unrounded.

// The polygon constants every window of the polygon carries (one record = one convex piece).
template <class P>
struct QuadPolygon {
  UInt<16> id;            // index in the frame's polygon list (priority order)
  bool opaque = true;     // non-opaque: screen door, never sets a mask
  SampleLevel colour[3];  // 0..255
  UInt<4> edge_count;     // used edge slots (the rest never reject: A = B = C = 0)
  EdgeGradient a[kQuadMaxEdges], b[kQuadMaxEdges];
  typename P::Gradient dp_di[kQuadParams], dp_dj[kQuadParams];
  Int<10> w_exponent;  // W value units: 1/Z = value * 2^w_exponent
  // The start window: the smallest window (level start_level, address start_x, start_y) holding
  // every lattice sample of the piece's bounding box (setup.hpp). With the architecture option
  // ArchConfig::start_window a PE above that level tests only the child on the path to it: the
  // other children hold no sample of the piece (cmodel/quadtree/arch_model.hpp).
  UInt<4> start_level;
  UInt<10> start_x, start_y;
};

// A window of level `level` with address (x, y): the state a PE reads.
template <class P>
struct QuadWindow {
  UInt<4> level;
  UInt<10> x, y;
  EdgeValue d[kQuadMaxEdges];        // per edge: the maximum of E over the window's samples
  typename P::Param f[kQuadParams];  // per parameter: the value at the window's top-left sample
  QuadPolygon<P> poly;
};

// What a PE decides for one child (sub-window) of a window.
template <class P>
struct QuadChild {
  bool masked = false;      // skipped: its priority-mask bit was set
  bool covered = false;     // may overlap the polygon (pixel level: some sample covered)
  bool full = false;        // every sample of the child is covered (set the mask if opaque)
  PixelSampleMask samples;  // pixel level: covered samples, bit S dj + di (screen door applied)
  QuadWindow<P> window;     // the child, valid when covered
};

// Setup output: up to three pieces, each a polygon record and its level-0 window.
template <class P>
struct QuadSetup {
  UInt<2> pieces;  // 0: degenerate (zero area), dropped
  QuadWindow<P> root[kQuadMaxPieces];
  UInt<3> bbox_edges[kQuadMaxPieces];  // bounding-box edges added per piece (statistics)
};

CIG_HLS_END_NAMESPACE
