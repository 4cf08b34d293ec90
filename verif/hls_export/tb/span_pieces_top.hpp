// Testbench case of span_pieces_top (hls/formatter/span_pieces.hpp): a formatted polygon and the
// raster size in; whether it is convex, or its span pieces (the crossing rule's coverage as
// disjoint pieces between two polygon edges over a range of sample rows) out.
#pragma once

#include "fields_span.hpp"

void span_pieces_top(const cig::hls::FormattedPrimitive& in, cig::hls::UInt<4> raster_log2, cig::hls::SpanPieces& out);

namespace cig {
namespace hls_tb {

struct SpanPiecesTopCase {
  static constexpr const char* kTop = "span_pieces_top";
  struct Input {
    hls::FormattedPrimitive in;
    hls::UInt<4> raster_log2;
  };
  struct Output {
    hls::SpanPieces out;
  };
  static void run(const Input& i, Output& o) { CIG_TB_DESIGN(span_pieces_top)(i.in, i.raster_log2, o.out); }
  template <class V>
  static void ports(V& v, const Input& i, const Output& o) {
    v("in", "in", "const FormattedPrimitive&", i.in);
    v("raster_log2", "in", "UInt<4>", i.raster_log2);
    v("out", "out", "SpanPieces&", o.out);
  }
};
template <>
struct Fields<SpanPiecesTopCase::Input> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.in, "in"), v(r.raster_log2, "raster_log2");
  }
};
template <>
struct Fields<SpanPiecesTopCase::Output> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.out, "out");
  }
};

}  // namespace hls_tb
}  // namespace cig
