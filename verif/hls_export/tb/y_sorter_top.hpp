// Testbench case of y_sorter_top (hls/segment/y_sorter.hpp). The segment memory is state, so a
// vector is a sequence: the memory before (reset for a raster, or nearly full), up to kCalls
// segments sorted one call each, then every call's result and the memory after.
#pragma once

#include "fields_segment.hpp"
#include "hls/segment/segment_arith.hpp"
#include "hls/segment/y_sorter.hpp"
#include "top_case.hpp"

CIG_TB_PORTS(y_sorter_top)

namespace cig {
namespace hls_tb {

namespace y_sorter_top_tb {

struct Case : Ports {
  static constexpr int kCalls = 64;
  using Memory = hls::SegmentMemory<hls::DefaultSegmentArith>;
  struct Input {
    Memory memory;
    int calls = 0;
    hls::Segment<hls::DefaultSegmentArith> s[kCalls];
  };
  struct Output {
    bool sorted[kCalls] = {};
    Memory memory;
  };
  static void run(const Input& i, Output& o) {
    o.memory = i.memory;
    for (int k = 0; k < i.calls && k < kCalls; ++k) o.sorted[k] = CIG_TB_DESIGN(y_sorter_top)(i.s[k], o.memory);
  }
};

}  // namespace y_sorter_top_tb
using YSorterTopCase = y_sorter_top_tb::Case;
template <>
struct Fields<YSorterTopCase::Input> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.memory, "memory"), v(r.calls, "calls"), v(r.s, "s");
  }
};
template <>
struct Fields<YSorterTopCase::Output> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.sorted, "sorted"), v(r.memory, "memory");
  }
};

}  // namespace hls_tb
}  // namespace cig
