// Testbench case of light_segments_top (hls/segment/light_segments.hpp): a formatted light point
// in, one whole-line segment per sample row its disc covers out, with their count (SPEC D).
#pragma once

#include "fields_segment.hpp"
#include "hls/segment/light_segments.hpp"
#include "hls/segment/segment_arith.hpp"

int light_segments_top(const cig::hls::FormattedPrimitive& light, cig::hls::UInt<4> raster_log2,
                       cig::hls::UInt<3> channel,
                       cig::hls::Segment<cig::hls::DefaultSegmentArith> (&out)[cig::hls::kMaxLightSegments]);

namespace cig {
namespace hls_tb {

struct LightSegmentsTopCase {
  static constexpr const char* kTop = "light_segments_top";
  struct Input {
    hls::FormattedPrimitive light;
    hls::UInt<4> raster_log2;
    hls::UInt<3> channel;
  };
  struct Output {
    int count = 0;
    hls::Segment<hls::DefaultSegmentArith> out[hls::kMaxLightSegments];
  };
  static void run(const Input& i, Output& o) {
    o.count = CIG_TB_DESIGN(light_segments_top)(i.light, i.raster_log2, i.channel, o.out);
  }
  template <class V>
  static void ports(V& v, const Input& i, const Output& o) {
    v("light", "in", "const FormattedPrimitive&", i.light);
    v("raster_log2", "in", "UInt<4>", i.raster_log2);
    v("channel", "in", "UInt<3>", i.channel);
    v("out", "out", "Segment<DefaultSegmentArith> (&)[kMaxLightSegments]", o.out);
    v("return", "out", "int", o.count);
  }
};
template <>
struct Fields<LightSegmentsTopCase::Input> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.light, "light"), v(r.raster_log2, "raster_log2"), v(r.channel, "channel");
  }
};
template <>
struct Fields<LightSegmentsTopCase::Output> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.count, "count"), v(r.out, "out");
  }
};

}  // namespace hls_tb
}  // namespace cig
