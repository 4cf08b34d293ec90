// Testbench case of span_piece_edges_top (hls/segment/span_piece_edges.hpp): a formatted polygon,
// one of its span pieces and the raster size in; the piece's frame-memory entry (the polygon's
// header over the piece's rows, one edge on each side) out.
#pragma once

#include "fields_segment.hpp"
#include "fields_span.hpp"
#include "hls/segment/segment_arith.hpp"

void span_piece_edges_top(const cig::hls::FormattedPrimitive& in, const cig::hls::SpanPiece& piece,
                          cig::hls::UInt<4> raster_log2, cig::hls::PolygonEdges<cig::hls::DefaultSegmentArith>& out);

namespace cig {
namespace hls_tb {

struct SpanPieceEdgesTopCase {
  static constexpr const char* kTop = "span_piece_edges_top";
  struct Input {
    hls::FormattedPrimitive in;
    hls::SpanPiece piece;
    hls::UInt<4> raster_log2;
  };
  struct Output {
    hls::PolygonEdges<hls::DefaultSegmentArith> out;
  };
  static void run(const Input& i, Output& o) {
    CIG_TB_DESIGN(span_piece_edges_top)(i.in, i.piece, i.raster_log2, o.out);
  }
  template <class V>
  static void ports(V& v, const Input& i, const Output& o) {
    v("in", "in", "const FormattedPrimitive&", i.in);
    v("piece", "in", "const SpanPiece&", i.piece);
    v("raster_log2", "in", "UInt<4>", i.raster_log2);
    v("out", "out", "PolygonEdges<DefaultSegmentArith>&", o.out);
  }
};
template <>
struct Fields<SpanPieceEdgesTopCase::Input> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.in, "in"), v(r.piece, "piece"), v(r.raster_log2, "raster_log2");
  }
};
template <>
struct Fields<SpanPieceEdgesTopCase::Output> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.out, "out");
  }
};

}  // namespace hls_tb
}  // namespace cig
