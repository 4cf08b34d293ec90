// Edge generator and preprocessor (SPEC D, seed 001): splits a formatted convex polygon into its
// left and right chains, computes each edge's slope (eq. 2) and first crossing, the polygon's area
// (eq. 5-6) and area code, and the raster lines it crosses per field (for overload protection).
//
// The seed rejects vertices closer than one raster line in Y to the previous one, except the Y
// extremes. Here the same rule is applied at the spacing of the sample rows the anti-aliasing
// uses: an edge is kept only when a sample row lies in [Y_begin, Y_end); a shorter edge cannot
// change any row's crossing, so dropping it is exact. A polygon no sample row crosses is
// degenerate and dropped whole.
#pragma once

#include "hls/segment/segment_arith.hpp"
#include "hls/types/top_ports.hpp"

CIG_HLS_BEGIN_NAMESPACE

namespace detail {

// Appends the edge a -> b (a above b) to a chain when a sample row crosses it.
template <class P, class Q>
void add_chain_edge(const FormattedVertexT<Q>& a, const FormattedVertexT<Q>& b, const LatticeGeometry& g, int rows,
                    Edge<P>* chain, UInt<5>& count) {
  if (!(a.y < b.y)) return;  // horizontal
  int first = P::first_row_at_or_after(g, a.y);
  int last = P::first_row_at_or_after(g, b.y) - 1;
  if (first < 0) first = 0;
  if (last > rows - 1) last = rows - 1;
  if (first > last) return;  // no sample row in [Ya, Yb): cannot change any crossing
  Edge<P>& e = chain[count.value()];
  e.row_first = first;
  e.row_last = last;
  e.x_begin = a.x;
  e.y_begin = a.y;
  e.x_end = b.x;
  e.y_end = b.y;
  e.i_begin = a.i;
  e.i_end = b.i;
  e.z_begin = a.z;
  e.z_end = b.z;
  e.dx_per_row = P::slope_per_row(g, a.x, a.y, b.x, b.y);
  e.x_first = P::crossing(g, a.x, a.y, b.x, b.y, first);
  count = UInt<5>(count.value() + 1);
}

}  // namespace detail

namespace detail {

// The header fields that come from the whole polygon: identity, colour, flags, eq. 5-6's area and
// the area code; no rows, no edges yet.
template <class P, class Q>
typename P::Area polygon_header(const FormattedPrimitiveT<Q>& in, PolygonHeader<P>& h) {
  h.id = in.id;
  for (int c = 0; c < 3; ++c) h.colour[c] = in.colour[c];
  h.opaque = in.opaque;
  h.protect = in.protect;
  h.left_count = UInt<5>(0);
  h.right_count = UInt<5>(0);
  h.row_first = 0;
  h.row_last = -1;
  h.segments_even = UInt<11>(0);
  h.segments_odd = UInt<11>(0);
  const int n = int(in.n.value());
  typename P::Area twice = typename P::Area();
  for (int j = 0; j < kMaxVertices; ++j) {
    if (j >= n) break;
    const int j1 = j + 1 == n ? 0 : j + 1;
    twice = P::area_sub(twice, P::area_term(in.v[j].x, in.v[j].y, in.v[j1].x, in.v[j1].y));
  }
  h.twice_area = twice;
  h.area_code = UInt<4>(in.protect ? 0 : P::area_code(twice));
  return twice;
}

// Raster lines crossed per field: even lines go to one segment-memory bank, odd lines to the other.
template <class P>
void count_lines(PolygonHeader<P>& h, int side_log2) {
  const int line_first = h.row_first >> side_log2, line_last = h.row_last >> side_log2;
  const int lines = line_last - line_first + 1;
  const int even = (lines + ((line_first & 1) == 0 ? 1 : 0)) >> 1;
  h.segments_even = UInt<11>(even);
  h.segments_odd = UInt<11>(lines - even);
}

}  // namespace detail

// raster_log2 = n for an N = 2^n raster (kMinRasterLog2..kMaxRasterLog2), side_log2 = t for
// S = 2^t sample rows per line (lattice_supported).
template <class P, class Q>
void generate_edges(const FormattedPrimitiveT<Q>& in, int raster_log2, PolygonEdges<P>& out,
                    int side_log2 = kDefaultSideLog2) {
  const LatticeGeometry g = LatticeGeometry::for_raster(raster_log2, side_log2);
  const int rows = g.rows();
  const int n = int(in.n.value());
  PolygonHeader<P>& h = out.h;
  out.valid = false;
  const typename P::Area twice = detail::polygon_header(in, h);
  P::fit_planes(in, raster_log2, false, h.planes, side_log2);
  int top = 0, bottom = 0;  // the Y extremes
  for (int j = 0; j < kMaxVertices; ++j) {
    if (j >= n) break;
    if (in.v[j].y < in.v[top].y) top = j;
    if (in.v[bottom].y < in.v[j].y) bottom = j;
  }
  if (n < 3 || P::is_zero(twice)) return;
  // eq. 6's area is -(1/2) sum(x_j y_{j+1} - x_{j+1} y_j); with Y pointing down a positive value
  // means the vertices run counter-clockwise on screen, so walking forward from the top vertex
  // follows the left side.
  const bool forward_is_left = P::is_positive(twice);
  Edge<P>* fwd = forward_is_left ? out.left : out.right;
  Edge<P>* bwd = forward_is_left ? out.right : out.left;
  UInt<5>& fwd_count = forward_is_left ? h.left_count : h.right_count;
  UInt<5>& bwd_count = forward_is_left ? h.right_count : h.left_count;
  int a = top;
  for (int k = 0; k < kMaxVertices; ++k) {  // forward chain: top -> bottom by increasing index
    if (a == bottom) break;
    const int b = a + 1 == n ? 0 : a + 1;
    detail::add_chain_edge<P>(in.v[a], in.v[b], g, rows, fwd, fwd_count);
    a = b;
  }
  a = top;
  for (int k = 0; k < kMaxVertices; ++k) {  // backward chain: top -> bottom by decreasing index
    if (a == bottom) break;
    const int b = a == 0 ? n - 1 : a - 1;
    detail::add_chain_edge<P>(in.v[a], in.v[b], g, rows, bwd, bwd_count);
    a = b;
  }
  if (h.left_count.value() == 0 || h.right_count.value() == 0) return;  // degenerate

  // Both chains span the same rows: those with Y in [Y_top, Y_bottom).
  const int lc = int(h.left_count.value());
  h.row_first = out.left[0].row_first;
  h.row_last = out.left[lc - 1].row_last;
  detail::count_lines(h, side_log2);
  out.valid = true;
}

// Top function (HLS): the default format.
// Ports (hls/types/top_ports.hpp): name, direction, interface, C++ type.
#define CIG_HLS_PORTS_edge_generator_top(PORT, ARRAY, RESULT) \
  RESULT(void)                                                \
  PORT(in, in, ap_none, const FormattedPrimitive&)            \
  PORT(raster_log2, in, ap_none, UInt<4>)                     \
  PORT(out, out, ap_vld, PolygonEdges<DefaultSegmentArith>&)
inline CIG_HLS_TOP(edge_generator_top) { generate_edges<DefaultSegmentArith>(in, int(raster_log2.value()), out); }

CIG_HLS_END_NAMESPACE
