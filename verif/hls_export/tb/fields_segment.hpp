// Field lists (vector_io.hpp) of the segment processor's records (hls/segment/records.hpp) and of
// the segment memory the Y sorter writes and the video channel reads (hls/segment/y_sorter.hpp).
#pragma once

#include "fields_formatter.hpp"
#include "hls/segment/records.hpp"
#include "hls/segment/y_sorter.hpp"

namespace cig {
namespace hls_tb {

template <class P>
struct Fields<hls::Edge<P>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.row_first, "row_first"), v(r.row_last, "row_last"), v(r.x_begin, "x_begin"), v(r.y_begin, "y_begin");
    v(r.x_end, "x_end"), v(r.y_end, "y_end"), v(r.i_begin, "i_begin"), v(r.i_end, "i_end");
    v(r.z_begin, "z_begin"), v(r.z_end, "z_end"), v(r.dx_per_row, "dx_per_row"), v(r.x_first, "x_first");
  }
};
template <class P>
struct Fields<hls::AttributePlanes<P>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.d, "d"), v(r.e, "e"), v(r.f, "f"), v(r.w_exponent, "w_exponent");
  }
};
template <class P>
struct Fields<hls::PolygonHeader<P>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.id, "id"), v(r.colour, "colour"), v(r.opaque, "opaque"), v(r.protect, "protect");
    v(r.area_code, "area_code"), v(r.twice_area, "twice_area"), v(r.row_first, "row_first");
    v(r.row_last, "row_last"), v(r.segments_even, "segments_even"), v(r.segments_odd, "segments_odd");
    v(r.left_count, "left_count"), v(r.right_count, "right_count"), v(r.planes, "planes");
  }
};
template <class P>
struct Fields<hls::PolygonEdges<P>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.valid, "valid"), v(r.h, "h"), v(r.left, "left"), v(r.right, "right");
  }
};
template <class P>
struct Fields<hls::Segment<P>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.line, "line"), v(r.type, "type"), v(r.row_first, "row_first"), v(r.row_last, "row_last");
    v(r.xl, "xl"), v(r.xr, "xr"), v(r.il, "il"), v(r.ir, "ir"), v(r.zl, "zl"), v(r.zr, "zr");
    v(r.source, "source"), v(r.is_light, "is_light"), v(r.opaque, "opaque"), v(r.channel, "channel");
  }
};
template <class P, int K>
struct Fields<hls::SegmentMemory<P, K>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.seg, "seg"), v(r.next, "next"), v(r.used, "used"), v(r.head, "head"), v(r.tail, "tail");
    v(r.count, "count"), v(r.dropped, "dropped");
  }
};

}  // namespace hls_tb
}  // namespace cig
