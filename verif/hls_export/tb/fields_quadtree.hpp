// Field lists (vector_io.hpp) of the quadtree raster processor's records (hls/quadtree/records.hpp).
#pragma once

#include "fields_formatter.hpp"
#include "hls/quadtree/records.hpp"

namespace cig {
namespace hls_tb {

template <class P>
struct Fields<hls::QuadPolygon<P>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.id, "id"), v(r.opaque, "opaque"), v(r.colour, "colour"), v(r.edge_count, "edge_count");
    v(r.a, "a"), v(r.b, "b"), v(r.dp_di, "dp_di"), v(r.dp_dj, "dp_dj"), v(r.w_exponent, "w_exponent");
  }
};
template <class P>
struct Fields<hls::QuadWindow<P>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.level, "level"), v(r.x, "x"), v(r.y, "y"), v(r.d, "d"), v(r.f, "f"), v(r.poly, "poly");
  }
};
template <class P>
struct Fields<hls::QuadChild<P>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.masked, "masked"), v(r.covered, "covered"), v(r.full, "full"), v(r.samples, "samples");
    v(r.window, "window");
  }
};
template <class P>
struct Fields<hls::QuadSetup<P>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.pieces, "pieces"), v(r.root, "root"), v(r.bbox_edges, "bbox_edges");
  }
};

}  // namespace hls_tb
}  // namespace cig
