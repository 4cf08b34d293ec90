// Setup of the recursive-subdivision raster processor (SPEC E, seed 004: "block 0"): from a
// formatted convex polygon, its edge lines A i + B j + C >= 0 in exact integers on the sample
// lattice (records.hpp), bounding-box edges that cut off the corners of the box, the level-0 coverage
// values d_0, and the parameter planes D i + E j + F of I and W = 1/Z.
//
// d_0. Seed 004: d_0 = A x_c + B y_c + C + [|A| (2^n - 1 + alpha) + |B| (2^n - 1 + beta)] / 2, the
// maximum of the edge function over the aperture-widened screen. On the 4N x 4N sample lattice
// (alpha = beta = 0, records.hpp; SN x SN for S samples a side) with x_c = y_c = (SN - 1) / 2
// this is d_0 = C + (SN - 1) (max(A, 0) + max(B, 0)): the value at the screen's corner sample that
// maximises the edge function, an integer.
//
// Edges. For the edge from vertex k to k+1 (half units hx, hy; dx, dy the differences) and the
// polygon's orientation sigma = sign(twice area):
//   E(i, j) = sigma [dx (s j + o - hy_k) - dy (s i + o - hx_k)]
//   A = -sigma dy s,  B = sigma dx s,  C = sigma [dx (o - hy_k) - dy (o - hx_k)] - (0 or 1):
// the reference's tie rule (cmodel/reference/coverage.hpp) gives a sample on the edge to the
// polygon when the inward gradient (A, B) points along +x, or along +y when A = 0; an edge that
// does not own its ties gets C - 1 (E is an integer, so E > 0 <=> E - 1 >= 0). Coverage is then
// exactly the reference's on the same (snapped) vertices, and polygons sharing an edge cover each
// sample once.
//
// Bounding box (seed 004, Fig. 2): windows near a corner of the polygon's box pass every edge
// test while lying outside the polygon (a rectangle turned 45 degrees costs about one extra window
// per level). A box edge (closed: it never rejects a sample the polygon covers) is added for each
// side of the box on which the polygon has no edge of its own, while edge slots remain. The seed
// bounds the number of box edges by the number of acute corners; that is enough near the pixel
// level, but a turned rectangle (no acute corner) then pays the corner windows at the coarse and
// middle levels, above eq. 2's bound (docs/results/architecture.md).
//
// Pieces. A polygon of more than kQuadMaxEdges vertices is split into a fan of pieces from vertex
// 0 (8 + 7 + 3 more vertices), sharing diagonals: exact and watertight by the tie rule. A polygon
// that snapping made non-convex is set up span piece by span piece instead (span_setup.hpp).
#pragma once

#include "hls/formatter/records.hpp"
#include "hls/quadtree/quadtree_arith.hpp"
#include "hls/types/top_ports.hpp"

CIG_HLS_BEGIN_NAMESPACE

// Setup input: positions on the formatter grid, values as the policy reads them.
template <class P>
struct QuadVertexInput {
  UInt<12> x, y;          // formatter grid units (eq. 1)
  typename P::VertexI i;  // intensity
  typename P::VertexZ z;  // depth
};

template <class P>
struct QuadPrimitiveInput {
  UInt<5> n;  // 3..16
  QuadVertexInput<P> v[kMaxVertices];
  SampleLevel colour[3];
  bool opaque = true;
  UInt<16> id;
};

namespace quad_detail {

// The edge function of the directed edge (hx0, hy0) -> (hx1, hy1) on the sample lattice, with
// the tie rule folded into C.
inline void edge_line(int hx0, int hy0, int hx1, int hy1, int sigma, int ls, int o, EdgeGradient& a, EdgeGradient& b,
                      Int<29>& c) {
  const int dx = hx1 - hx0, dy = hy1 - hy0;  // |.| <= 8190
  const int av = -sigma * dy * (1 << ls), bv = sigma * dx * (1 << ls);
  const std::int64_t cv = std::int64_t(sigma) * (std::int64_t(dx) * (o - hy0) - std::int64_t(dy) * (o - hx0));
  const bool owns_ties = av > 0 || (av == 0 && bv > 0);
  a = EdgeGradient(av);
  b = EdgeGradient(bv);
  c = Int<29>(cv - (owns_ties ? 0 : 1));
}

// ceil(t / 2^ls) and floor(t / 2^ls) for any integer t (arithmetic shift is floor).
inline int ceil_shift(int t, int ls) { return (t + (1 << ls) - 1) >> ls; }
inline int floor_shift(int t, int ls) { return t >> ls; }

// d_0: the edge function at the screen corner sample that maximises it.
inline EdgeValue root_coverage(const EdgeGradient& a, const EdgeGradient& b, const Int<29>& c,
                               const LatticeGeometry& g) {
  const std::int64_t span = std::int64_t{g.rows()} - 1;  // SN - 1 sample steps
  const std::int64_t ap = a.value() > 0 ? a.value() : 0, bp = b.value() > 0 ? b.value() : 0;
  return EdgeValue(c.value() + span * (ap + bp));
}

// The start window of a piece (records.hpp QuadPolygon::start_level): the deepest level l <= n
// whose one window holds the sample box [i0, i1] x [j0, j1] (lattice samples, clamped to the
// lattice), and that window's address. A box with no sample keeps the whole screen (level 0).
template <class P>
void set_start_window(int i0, int i1, int j0, int j1, const LatticeGeometry& g, QuadPolygon<P>& poly) {
  const int last = g.rows() - 1;
  i0 = i0 < 0 ? 0 : i0;
  j0 = j0 < 0 ? 0 : j0;
  i1 = i1 > last ? last : i1;
  j1 = j1 > last ? last : j1;
  int level = 0;
  if (i0 <= i1 && j0 <= j1) {
    for (int l = 1; l <= kQuadMaxLevels; ++l) {
      if (l > g.raster_log2) break;
      const int sh = g.raster_log2 - l + g.side_log2;  // a level-l window has 2^sh samples a side
      if ((i0 >> sh) == (i1 >> sh) && (j0 >> sh) == (j1 >> sh)) level = l;
    }
  }
  const int sh = g.raster_log2 - level + g.side_log2;
  poly.start_level = UInt<4>(level);
  poly.start_x = UInt<10>(level == 0 ? 0 : i0 >> sh);
  poly.start_y = UInt<10>(level == 0 ? 0 : j0 >> sh);
}

// The samples of the half-unit box [h0, h1] along one axis: ceil((h0 - o) / s) .. floor((h1 - o) / s),
// the bounding-box edges' bounds below.
inline void box_samples(int h0, int h1, const LatticeGeometry& g, int& k0, int& k1) {
  k0 = ceil_shift(h0 - g.offset_half, g.log2_half_spacing);
  k1 = floor_shift(h1 - g.offset_half, g.log2_half_spacing);
}

// Bounding-box edges: left, right, top, bottom, each unless a polygon edge already lies on that
// side of the box (an axis-aligned edge at the extreme), appended after the piece's `used` edges;
// returns how many were added. extreme: the box (hx min, hx max, hy min, hy max).
template <class P>
int add_box_edges(const int (&hx)[kMaxVertices], const int (&hy)[kMaxVertices], const int (&idx)[kQuadMaxEdges], int m,
                  const LatticeGeometry& g, int& used, int (&extreme)[4], QuadWindow<P>& root) {
  const int ls = g.log2_half_spacing;
  const int o = g.offset_half;
  for (int k = 0; k < 4; ++k) extreme[k] = k < 2 ? hx[idx[0]] : hy[idx[0]];
  for (int k = 1; k < kQuadMaxEdges; ++k) {
    if (k >= m) break;
    if (hx[idx[k]] < extreme[0]) extreme[0] = hx[idx[k]];
    if (hx[idx[k]] > extreme[1]) extreme[1] = hx[idx[k]];
    if (hy[idx[k]] < extreme[2]) extreme[2] = hy[idx[k]];
    if (hy[idx[k]] > extreme[3]) extreme[3] = hy[idx[k]];
  }
  bool on_side[4] = {false, false, false, false};
  for (int k = 0; k < kQuadMaxEdges; ++k) {
    if (k >= m) break;
    const int a = idx[k], b = idx[k + 1 == m ? 0 : k + 1];
    if (hx[a] == hx[b] && hx[a] == extreme[0]) on_side[0] = true;
    if (hx[a] == hx[b] && hx[a] == extreme[1]) on_side[1] = true;
    if (hy[a] == hy[b] && hy[a] == extreme[2]) on_side[2] = true;
    if (hy[a] == hy[b] && hy[a] == extreme[3]) on_side[3] = true;
  }
  int added = 0;
  for (int side = 0; side < 4; ++side) {
    if (used >= kQuadMaxEdges) break;
    if (on_side[side]) continue;  // the polygon's own edge is that side of the box
    const int t = extreme[side] - o;
    int av = 0, bv = 0, cv = 0;
    if (side == 0) {
      av = 1;
      cv = -ceil_shift(t, ls);
    }  // i >= ceil((hx_min - o) / s)
    else if (side == 1) {
      av = -1;
      cv = floor_shift(t, ls);
    }  // i <= floor((hx_max - o) / s)
    else if (side == 2) {
      bv = 1;
      cv = -ceil_shift(t, ls);
    } else {
      bv = -1;
      cv = floor_shift(t, ls);
    }
    root.poly.a[used] = EdgeGradient(av);
    root.poly.b[used] = EdgeGradient(bv);
    root.d[used] = root_coverage(root.poly.a[used], root.poly.b[used], Int<29>(cv), g);
    ++used;
    ++added;
  }
  return added;
}

// Parameter planes (Newell, hls/pixel/attribute_planes.hpp): the piece's gradients and the root
// window's values.
template <class P>
void set_piece_planes(const QuadPrimitiveInput<P>& in, const int (&hx)[kMaxVertices], const int (&hy)[kMaxVertices],
                      const int (&idx)[kQuadMaxEdges], int m, const Int<34>& nz, const LatticeGeometry& g, int e_min,
                      QuadWindow<P>& root) {
  QuadPolygon<P>& poly = root.poly;
  typename P::VertexI vi[kMaxVertices];
  typename P::VertexZ vz[kMaxVertices];
  for (int k = 0; k < kMaxVertices; ++k) {
    vi[k] = in.v[k].i;
    vz[k] = in.v[k].z;
  }
  AttributePlanes<P> planes;
  fit_attribute_planes<P>(vi, vz, hx, hy, idx, m, nz, g.raster_log2, e_min, planes, g.side_log2);
  for (int p = 0; p < kQuadParams; ++p) {
    poly.dp_di[p] = planes.d[p];
    poly.dp_dj[p] = planes.e[p];
    root.f[p] = planes.f[p];
  }
  poly.w_exponent = planes.w_exponent;
}

// One convex piece: vertices idx[0..m) of the input (half units hx, hy given).
template <class P>
void setup_piece(const QuadPrimitiveInput<P>& in, const int (&hx)[kMaxVertices], const int (&hy)[kMaxVertices],
                 const int (&idx)[kQuadMaxEdges], int m, const LatticeGeometry& g, int e_min, QuadWindow<P>& root,
                 UInt<3>& bbox_added, bool& ok) {
  const int ls = g.log2_half_spacing;  // log2 s
  const int o = g.offset_half;         // half-unit position of sample 0
  // Twice the signed area (Newell's nz; eq. 5-6 of seed 001 has the same sum).
  Int<34> nz(0);
  for (int k = 0; k < kQuadMaxEdges; ++k) {
    if (k >= m) break;
    const int k1 = k + 1 == m ? 0 : k + 1;
    const int a = idx[k], b = idx[k1];
    nz = wrap<34>(nz + Int<15>(hx[a] - hx[b]) * Int<15>(hy[a] + hy[b]));
  }
  ok = nz.value() != 0;
  if (!ok) return;
  const int sigma = nz.value() > 0 ? 1 : -1;

  QuadPolygon<P>& poly = root.poly;
  poly.id = in.id;
  poly.opaque = in.opaque;
  for (int c = 0; c < 3; ++c) poly.colour[c] = in.colour[c];
  root.level = UInt<4>(0);
  root.x = UInt<10>(0);
  root.y = UInt<10>(0);
  int used = 0;
  for (int k = 0; k < kQuadMaxEdges; ++k) {
    Int<29> c(0);
    poly.a[k] = EdgeGradient(0);
    poly.b[k] = EdgeGradient(0);
    if (k < m) {
      const int k1 = k + 1 == m ? 0 : k + 1;
      edge_line(hx[idx[k]], hy[idx[k]], hx[idx[k1]], hy[idx[k1]], sigma, ls, o, poly.a[k], poly.b[k], c);
      used = k + 1;
    }
    root.d[k] = root_coverage(poly.a[k], poly.b[k], c, g);
  }

  int extreme[4];  // the box: hx min, hx max, hy min, hy max
  bbox_added = UInt<3>(add_box_edges<P>(hx, hy, idx, m, g, used, extreme, root));
  poly.edge_count = UInt<4>(used);
  int i0, i1, j0, j1;
  box_samples(extreme[0], extreme[1], g, i0, i1);
  box_samples(extreme[2], extreme[3], g, j0, j1);
  set_start_window(i0, i1, j0, j1, g, poly);

  set_piece_planes<P>(in, hx, hy, idx, m, nz, g, e_min, root);
}

}  // namespace quad_detail

// Setup of one polygon: drops repeated consecutive vertices (the formatter can merge two), splits
// it into pieces of at most kQuadMaxEdges vertices, and sets up each piece. raster_log2 = n,
// side_log2 = t (S = 2^t samples a side per pixel).
template <class P>
void quadtree_setup(const QuadPrimitiveInput<P>& in, int raster_log2, QuadSetup<P>& out,
                    int side_log2 = kDefaultSideLog2) {
  const LatticeGeometry g = LatticeGeometry::for_raster(raster_log2, side_log2);
  int hx[kMaxVertices], hy[kMaxVertices], keep[kMaxVertices];
  int m = 0;
  const int n = int(in.n.value());
  for (int k = 0; k < kMaxVertices; ++k) {
    hx[k] = 0;
    hy[k] = 0;
    keep[k] = 0;
    if (k >= n) continue;
    const int x2 = 2 * int(in.v[k].x.value()), y2 = 2 * int(in.v[k].y.value());
    if (m > 0 && x2 == hx[m - 1] && y2 == hy[m - 1]) continue;
    hx[m] = x2;
    hy[m] = y2;
    keep[m] = k;
    ++m;
  }
  for (int k = 0; k < kMaxVertices; ++k) {  // closing duplicates
    if (m <= 1 || !(hx[m - 1] == hx[0] && hy[m - 1] == hy[0])) break;
    --m;
  }
  // Positions re-indexed by kept vertex; values read through keep[].
  QuadPrimitiveInput<P> kept = in;
  for (int k = 0; k < kMaxVertices; ++k) {
    if (k >= m) break;
    kept.v[k] = in.v[keep[k]];
  }
  // The nearest binade of the polygon's depths: the block exponent of W.
  int e_min = 255;
  for (int k = 0; k < kMaxVertices; ++k) {
    if (k >= m) break;
    const int e = P::depth_exponent(kept.v[k].z);
    if (e < e_min) e_min = e;
  }
  out.pieces = UInt<2>(0);
  if (m < 3) return;
  int count = 0;
  int first = 1;  // each piece: vertex 0 and vertices first..last
  for (int piece = 0; piece < kQuadMaxPieces; ++piece) {
    if (first >= m - 1) break;
    int idx[kQuadMaxEdges];
    idx[0] = 0;
    int len = 1;
    for (int k = 0; k < kQuadMaxEdges - 1; ++k) {
      idx[k + 1] = 0;
      if (first + k >= m) continue;
      idx[k + 1] = first + k;
      len = k + 2;
    }
    bool ok = false;
    UInt<3> bbox;
    quad_detail::setup_piece(kept, hx, hy, idx, len, g, e_min, out.root[count], bbox, ok);
    if (ok) {
      out.bbox_edges[count] = bbox;
      ++count;
    }
    first += len - 2;
  }
  out.pieces = UInt<2>(count);
}

// The setup input of the bit-accurate policies: the formatter's output as it is.
template <class P>
void quad_input_from_formatted(const FormattedPrimitive& f, QuadPrimitiveInput<P>& in) {
  in.n = f.n;
  for (int k = 0; k < kMaxVertices; ++k) {
    in.v[k].x = f.v[k].x;
    in.v[k].y = f.v[k].y;
    in.v[k].i = f.v[k].i;
    in.v[k].z = f.v[k].z;
  }
  for (int c = 0; c < 3; ++c) in.colour[c] = f.colour[c];
  in.opaque = f.opaque;
  in.id = f.id;
}

// Top function (HLS): one formatted polygon, the default format.
// Ports (hls/types/top_ports.hpp): name, direction, interface, C++ type.
#define CIG_HLS_PORTS_quadtree_setup_top(PORT, ARRAY, RESULT) \
  RESULT(void)                                                \
  PORT(f, in, ap_none, const FormattedPrimitive&)             \
  PORT(raster_log2, in, ap_none, UInt<4>)                     \
  PORT(out, out, ap_vld, QuadSetup<DefaultQuadArith>&)
inline CIG_HLS_TOP(quadtree_setup_top) {
  QuadPrimitiveInput<DefaultQuadArith> in;
  quad_input_from_formatted(f, in);
  quadtree_setup(in, int(raster_log2.value()), out);
}

CIG_HLS_END_NAMESPACE
