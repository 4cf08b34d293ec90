// Testbench case of edge_generator_top (hls/segment/edge_generator.hpp): a formatted polygon and
// the raster size in, its header and left/right edge chains out (SPEC D eq. 2, 5, 6).
#pragma once

#include "fields_segment.hpp"
#include "hls/segment/segment_arith.hpp"

void edge_generator_top(const cig::hls::FormattedPrimitive& in, cig::hls::UInt<4> raster_log2,
                        cig::hls::PolygonEdges<cig::hls::DefaultSegmentArith>& out);

namespace cig {
namespace hls_tb {

struct EdgeGeneratorTopCase {
  static constexpr const char* kTop = "edge_generator_top";
  struct Input {
    hls::FormattedPrimitive in;
    hls::UInt<4> raster_log2;
  };
  struct Output {
    hls::PolygonEdges<hls::DefaultSegmentArith> out;
  };
  static void run(const Input& i, Output& o) { CIG_TB_DESIGN(edge_generator_top)(i.in, i.raster_log2, o.out); }
  template <class V>
  static void ports(V& v, const Input& i, const Output& o) {
    v("in", "in", "const FormattedPrimitive&", i.in);
    v("raster_log2", "in", "UInt<4>", i.raster_log2);
    v("out", "out", "PolygonEdges<DefaultSegmentArith>&", o.out);
  }
};
template <>
struct Fields<EdgeGeneratorTopCase::Input> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.in, "in"), v(r.raster_log2, "raster_log2");
  }
};
template <>
struct Fields<EdgeGeneratorTopCase::Output> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.out, "out");
  }
};

}  // namespace hls_tb
}  // namespace cig
