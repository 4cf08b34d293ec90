// Testbench case of frame_memory_write_top (hls/segment/frame_memory.hpp). The frame memory is
// state, so a vector is a sequence: the memory before, up to kCalls polygons written one call
// each, then every call's result and the memory after.
#pragma once

#include "fields_segment.hpp"
#include "hls/segment/frame_memory.hpp"
#include "hls/segment/segment_arith.hpp"
#include "top_case.hpp"

CIG_TB_PORTS(frame_memory_write_top)

namespace cig {
namespace hls_tb {

template <class P>
struct Fields<hls::FrameWord<P>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.is_header, "is_header"), v(r.header, "header"), v(r.edge, "edge");
  }
};
template <class P, int K>
struct Fields<hls::FrameMemory<P, K>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.bank, "bank"), v(r.used, "used"), v(r.write_bank, "write_bank");
    v(r.polygons_written, "polygons_written"), v(r.polygons_overflowed, "polygons_overflowed");
  }
};

namespace frame_memory_write_top_tb {

struct Case : Ports {
  static constexpr int kCalls = 48;
  using Memory = hls::FrameMemory<hls::DefaultSegmentArith>;
  struct Input {
    Memory memory;
    int calls = 0;
    hls::PolygonEdges<hls::DefaultSegmentArith> e[kCalls];
  };
  struct Output {
    bool written[kCalls] = {};
    Memory memory;
  };
  static void run(const Input& i, Output& o) {
    o.memory = i.memory;
    for (int k = 0; k < i.calls && k < kCalls; ++k)
      o.written[k] = CIG_TB_DESIGN(frame_memory_write_top)(i.e[k], o.memory);
  }
};

}  // namespace frame_memory_write_top_tb
using FrameMemoryWriteTopCase = frame_memory_write_top_tb::Case;
template <>
struct Fields<FrameMemoryWriteTopCase::Input> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.memory, "memory"), v(r.calls, "calls"), v(r.e, "e");
  }
};
template <>
struct Fields<FrameMemoryWriteTopCase::Output> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.written, "written"), v(r.memory, "memory");
  }
};

}  // namespace hls_tb
}  // namespace cig
