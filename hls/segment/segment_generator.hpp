// Segment generator (SPEC D, seed 001): for every raster line a polygon crosses, one segment:
// the left and right X at the first and last covered sample rows of the line (incremental
// stepping by the slope along each edge: the seed's "four X values"), the segment type (1 holds
// the polygon's top, 2 its bottom, 3 neither, 4 both) and I and Z at both ends by eq. 3-4,
// evaluated at the centre of the line's covered rows. X is stored for each covered sample row
// (records.hpp explains why).
#pragma once

#include "hls/segment/segment_arith.hpp"
#include "hls/types/top_ports.hpp"

CIG_HLS_BEGIN_NAMESPACE

namespace detail {

// Index of the chain edge that covers row k, searching forward from `from` (rows increase).
template <class P>
int edge_for_row(const Edge<P>* chain, int count, int from, int k) {
  int e = from;
  for (int s = 0; s < kMaxEdgesPerChain; ++s) {
    if (e + 1 >= count || chain[e].row_last >= k) break;
    ++e;
  }
  return e;
}

template <class P>
typename P::X x_at_row(const Edge<P>& e, int k) {
  return P::step(e.x_first, e.dx_per_row, k - e.row_first);
}

}  // namespace detail

// seed_quadrilateral: fill the middle rows by interpolating between the first and last covered
// rows, as the seed's four-X segment does (for measuring what that approximation costs).
// Writes the polygon's segments, top line first, to out[0..count); returns count.
template <class P>
int generate_segments(const PolygonEdges<P>& in, int raster_log2, UInt<3> channel, bool seed_quadrilateral,
                      Segment<P> (&out)[kMaxLines], int side_log2 = kDefaultSideLog2) {
  if (!in.valid) return 0;
  const LatticeGeometry g = LatticeGeometry::for_raster(raster_log2, side_log2);
  const int side = g.side();  // S sample rows per line
  const PolygonHeader<P>& h = in.h;
  const int lc = int(h.left_count.value()), rc = int(h.right_count.value());
  const int line_first = h.row_first >> side_log2, line_last = h.row_last >> side_log2;
  int le = 0, re = 0;  // current edges of the left and right chains
  int count = 0;
  for (int line = 0; line < kMaxLines; ++line) {
    const int L = line_first + line;
    if (L > line_last) break;
    const int top_row = side * L, bottom_row = side * L + side - 1;
    const int rf = h.row_first > top_row ? h.row_first : top_row;      // first covered row
    const int rl = h.row_last < bottom_row ? h.row_last : bottom_row;  // last covered row
    const int rm = (rf + rl) >> 1;                                     // the row I and Z use
    const int yt_quarter = g.sample_half(rf) + g.sample_half(rl);      // centre of rf..rl, quarter units
    Segment<P>& s = out[count++];
    s.line = UInt<10>(L);
    const bool top = rf == h.row_first, bottom = rl == h.row_last;
    s.type = UInt<3>(top && bottom ? kSegWhole : top ? kSegTop : bottom ? kSegBottom : kSegMiddle);
    s.row_first = UInt<3>(rf - top_row);
    s.row_last = UInt<3>(rl - top_row);
    int lm = le, rmi = re;
    for (int r = 0; r < kMaxRowsPerLine; ++r) {
      if (r >= side) break;
      const int k = top_row + r;
      if (k < rf || k > rl) continue;
      le = detail::edge_for_row(in.left, lc, le, k);  // X advances by the slope, edge by edge
      re = detail::edge_for_row(in.right, rc, re, k);
      s.xl[r] = detail::x_at_row(in.left[le], k);
      s.xr[r] = detail::x_at_row(in.right[re], k);
      if (k == rm) {
        lm = le;
        rmi = re;
      }
    }
    if (seed_quadrilateral && rl - rf >= 2) {
      const int a = rf - top_row, b = rl - top_row;
      for (int r = 1; r < kMaxRowsPerLine - 1; ++r) {
        if (r >= side - 1) break;
        if (r <= a || r >= b) continue;
        s.xl[r] = P::lerp_x(s.xl[a], s.xl[b], r - a, b - a);
        s.xr[r] = P::lerp_x(s.xr[a], s.xr[b], r - a, b - a);
      }
    }
    // Eq. 3-4 at the centre of the covered rows, on the edges that hold the middle row.
    const Edge<P>& el = in.left[lm];
    s.il = P::intensity_at(el.i_begin, el.i_end, el.y_begin, el.y_end, yt_quarter);
    s.zl = P::depth_at(el.z_begin, el.z_end, el.y_begin, el.y_end, yt_quarter);
    const Edge<P>& er = in.right[rmi];
    s.ir = P::intensity_at(er.i_begin, er.i_end, er.y_begin, er.y_end, yt_quarter);
    s.zr = P::depth_at(er.z_begin, er.z_end, er.y_begin, er.y_end, yt_quarter);
    s.source = h.id;
    s.is_light = false;
    s.opaque = h.opaque;
    s.channel = channel;
  }
  return count;
}

// Top function (HLS): the default format.
// Ports (hls/types/top_ports.hpp): name, direction, interface, C++ type.
#define CIG_HLS_PORTS_segment_generator_top(PORT, ARRAY, RESULT)  \
  RESULT(int)                                                     \
  PORT(in, in, ap_none, const PolygonEdges<DefaultSegmentArith>&) \
  PORT(raster_log2, in, ap_none, UInt<4>)                         \
  PORT(channel, in, ap_none, UInt<3>)                             \
  ARRAY(out, out, ap_memory, Segment<DefaultSegmentArith>, kMaxLines)
inline CIG_HLS_TOP(segment_generator_top) {
  return generate_segments<DefaultSegmentArith>(in, int(raster_log2.value()), channel, false, out);
}

CIG_HLS_END_NAMESPACE
