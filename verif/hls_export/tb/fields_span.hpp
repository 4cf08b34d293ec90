// Field lists (vector_io.hpp) of the span-piece records (hls/formatter/span_pieces.hpp).
#pragma once

#include "fields_formatter.hpp"
#include "hls/formatter/span_pieces.hpp"

namespace cig {
namespace hls_tb {

template <>
struct Fields<hls::SpanPiece> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.left_top, "left_top"), v(r.left_bottom, "left_bottom"), v(r.right_top, "right_top");
    v(r.right_bottom, "right_bottom"), v(r.row_first, "row_first"), v(r.row_last, "row_last");
  }
};
template <>
struct Fields<hls::SpanPieces> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.convex, "convex"), v(r.count, "count"), v(r.piece, "piece");
  }
};

}  // namespace hls_tb
}  // namespace cig
