// Field lists (vector_io.hpp) of the formatter's records (hls/formatter/records.hpp) and of the fog
// table every pixel stage reads (hls/pixel/sample_colour.hpp).
#pragma once

#include "hls/formatter/records.hpp"
#include "hls/pixel/sample_colour.hpp"
#include "vector_io.hpp"

namespace cig {
namespace hls_tb {

template <>
struct Fields<hls::RawVertex> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.xs, "xs"), v(r.ys, "ys"), v(r.zs, "zs"), v(r.is, "is");
  }
};
template <>
struct Fields<hls::RawPrimitive> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.is_light, "is_light"), v(r.n, "n"), v(r.v, "v"), v(r.ds, "ds"), v(r.colour, "colour");
    v(r.opaque, "opaque"), v(r.protect, "protect"), v(r.id, "id");
  }
};
template <class P>
struct Fields<hls::FormattedVertexT<P>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.x, "x"), v(r.y, "y"), v(r.i, "i"), v(r.z, "z");
  }
};
template <class P>
struct Fields<hls::FormattedPrimitiveT<P>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.is_light, "is_light"), v(r.n, "n"), v(r.v, "v"), v(r.d, "d"), v(r.colour, "colour");
    v(r.opaque, "opaque"), v(r.protect, "protect"), v(r.id, "id");
  }
};
template <>
struct Fields<hls::FogTable> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.f, "f");
  }
};

}  // namespace hls_tb
}  // namespace cig
