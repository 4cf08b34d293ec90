// Testbench case of video_channel_top (hls/segment/video_channel.hpp): a field's segment memory,
// the frame's colour and fog tables, and up to kLines raster lines in; each line's pixels and
// owner ids and the call's result out. The line buffer is the kernel's scratch memory: the
// testbench hands it a cleared one for each line, as the hardware's double buffer would.
#pragma once

#include <memory>

#include "fields_segment.hpp"
#include "hls/segment/segment_arith.hpp"
#include "hls/segment/video_channel.hpp"
#include "top_case.hpp"

CIG_TB_PORTS(video_channel_top)

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
template <class P>
struct Fields<hls::LineBuffer<P>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.rgb, "rgb"), v(r.owned, "owned"), v(r.polygon, "polygon"), v(r.owned_mask, "owned_mask");
    v(r.settled_mask, "settled_mask");
  }
};
template <>
struct Fields<hls::PixelLine> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.rgb, "rgb"), v(r.id, "id");
  }
};

namespace video_channel_top_tb {

struct Case : Ports {
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
};

}  // namespace video_channel_top_tb
using VideoChannelTopCase = video_channel_top_tb::Case;
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
