// Testbench case of quadtree_span_setup_top (hls/quadtree/span_setup.hpp): a formatted polygon, one
// of its span pieces and the raster size in; the piece's level-0 window (four edges, the polygon's
// parameter planes) and whether the polygon has any plane at all (ok) out.
#pragma once

#include "fields_quadtree.hpp"
#include "fields_span.hpp"
#include "hls/quadtree/quadtree_arith.hpp"

bool quadtree_span_setup_top(const cig::hls::FormattedPrimitive& f, const cig::hls::SpanPiece& piece,
                             cig::hls::UInt<4> raster_log2, cig::hls::QuadWindow<cig::hls::DefaultQuadArith>& root);

namespace cig {
namespace hls_tb {

struct QuadtreeSpanSetupTopCase {
  static constexpr const char* kTop = "quadtree_span_setup_top";
  struct Input {
    hls::FormattedPrimitive f;
    hls::SpanPiece piece;
    hls::UInt<4> raster_log2;
  };
  struct Output {
    bool ok = false;
    hls::QuadWindow<hls::DefaultQuadArith> root;
  };
  static void run(const Input& i, Output& o) {
    o.ok = CIG_TB_DESIGN(quadtree_span_setup_top)(i.f, i.piece, i.raster_log2, o.root);
  }
  template <class V>
  static void ports(V& v, const Input& i, const Output& o) {
    v("f", "in", "const FormattedPrimitive&", i.f);
    v("piece", "in", "const SpanPiece&", i.piece);
    v("raster_log2", "in", "UInt<4>", i.raster_log2);
    v("root", "out", "QuadWindow<DefaultQuadArith>&", o.root);
    v("return", "out", "bool", o.ok);
  }
};
template <>
struct Fields<QuadtreeSpanSetupTopCase::Input> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.f, "f"), v(r.piece, "piece"), v(r.raster_log2, "raster_log2");
  }
};
template <>
struct Fields<QuadtreeSpanSetupTopCase::Output> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.ok, "ok"), v(r.root, "root");
  }
};

}  // namespace hls_tb
}  // namespace cig
