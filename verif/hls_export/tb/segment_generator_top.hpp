// Testbench case of segment_generator_top (hls/segment/segment_generator.hpp): a polygon's edge
// chains in, one segment per raster line it crosses out, with their count (SPEC D).
#pragma once

#include "fields_segment.hpp"
#include "hls/segment/segment_arith.hpp"

int segment_generator_top(const cig::hls::PolygonEdges<cig::hls::DefaultSegmentArith>& in,
                          cig::hls::UInt<4> raster_log2, cig::hls::UInt<3> channel,
                          cig::hls::Segment<cig::hls::DefaultSegmentArith> (&out)[cig::hls::kMaxLines]);

namespace cig {
namespace hls_tb {

struct SegmentGeneratorTopCase {
  static constexpr const char* kTop = "segment_generator_top";
  struct Input {
    hls::PolygonEdges<hls::DefaultSegmentArith> in;
    hls::UInt<4> raster_log2;
    hls::UInt<3> channel;
  };
  struct Output {
    int count = 0;
    hls::Segment<hls::DefaultSegmentArith> out[hls::kMaxLines];
  };
  static void run(const Input& i, Output& o) {
    o.count = CIG_TB_DESIGN(segment_generator_top)(i.in, i.raster_log2, i.channel, o.out);
  }
  template <class V>
  static void ports(V& v, const Input& i, const Output& o) {
    v("in", "in", "const PolygonEdges<DefaultSegmentArith>&", i.in);
    v("raster_log2", "in", "UInt<4>", i.raster_log2);
    v("channel", "in", "UInt<3>", i.channel);
    v("out", "out", "Segment<DefaultSegmentArith> (&)[kMaxLines]", o.out);
    v("return", "out", "int", o.count);
  }
};
template <>
struct Fields<SegmentGeneratorTopCase::Input> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.in, "in"), v(r.raster_log2, "raster_log2"), v(r.channel, "channel");
  }
};
template <>
struct Fields<SegmentGeneratorTopCase::Output> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.count, "count"), v(r.out, "out");
  }
};

}  // namespace hls_tb
}  // namespace cig
