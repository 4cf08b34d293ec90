// Testbench case of video_channel_top (hls/segment/video_channel.hpp): a field's segment memory,
// the frame's colour and fog tables, and up to kLines raster lines in; each line's pixels and
// owner ids and the call's result out. The line buffer is the kernel's scratch memory: the
// testbench hands it a cleared one for each line, as the hardware's double buffer would.
#pragma once

#include <memory>

#include "fields_segment.hpp"
#include "hls/segment/segment_arith.hpp"
#include "hls/segment/video_channel.hpp"

int video_channel_top(cig::hls::UInt<10> line, cig::hls::UInt<4> raster_log2,
                      const cig::hls::SegmentMemory<cig::hls::DefaultSegmentArith>& m,
                      const cig::hls::VideoTables<cig::hls::DefaultSegmentArith>& t,
                      cig::hls::LineBuffer<cig::hls::DefaultSegmentArith>& w, cig::hls::PixelLine& out);

namespace cig {
namespace hls_tb {

template <class P>
struct Fields<hls::VideoTables<P>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.polygon_colour, "polygon_colour"), v(r.light_colour, "light_colour"), v(r.fog, "fog");
    v(r.fog_colour, "fog_colour"), v(r.background, "background"), v(r.plane_mode, "plane_mode");
    v(r.polygon_planes, "polygon_planes"), v(r.fog_inverse, "fog_inverse");
  }
};
template <>
struct Fields<hls::PixelLine> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.rgb, "rgb"), v(r.id, "id");
  }
};

struct VideoChannelTopCase {
  static constexpr const char* kTop = "video_channel_top";
  static constexpr int kLines = 8;
  using P = hls::DefaultSegmentArith;
  struct Input {
    hls::UInt<4> raster_log2;
    hls::SegmentMemory<P> memory;
    hls::VideoTables<P> tables;
    int lines = 0;
    hls::UInt<10> line[kLines];
  };
  struct Output {
    int result[kLines] = {};
    hls::PixelLine out[kLines];
  };
  static void run(const Input& i, Output& o) {
    for (int k = 0; k < i.lines && k < kLines; ++k) {
      const auto scratch = std::make_unique<hls::LineBuffer<P>>();
      o.result[k] = CIG_TB_DESIGN(video_channel_top)(i.line[k], i.raster_log2, i.memory, i.tables, *scratch, o.out[k]);
    }
  }
  template <class V>
  static void ports(V& v, const Input& i, const Output& o) {
    v("line", "in", "UInt<10>", i.line[0]);
    v("raster_log2", "in", "UInt<4>", i.raster_log2);
    v("m", "in", "const SegmentMemory<DefaultSegmentArith>&", i.memory);
    v("t", "in", "const VideoTables<DefaultSegmentArith>&", i.tables);
    v("out", "out", "PixelLine&", o.out[0]);
    v("return", "out", "int", o.result[0]);
  }
};
template <>
struct Fields<VideoChannelTopCase::Input> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.raster_log2, "raster_log2"), v(r.memory, "memory"), v(r.tables, "tables"), v(r.lines, "lines");
    v(r.line, "line");
  }
};
template <>
struct Fields<VideoChannelTopCase::Output> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.result, "result"), v(r.out, "out");
  }
};

}  // namespace hls_tb
}  // namespace cig
