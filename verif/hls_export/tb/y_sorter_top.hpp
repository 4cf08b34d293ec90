// Testbench case of y_sorter_top (hls/segment/y_sorter.hpp). The segment memory is state, so a
// vector is a sequence: the memory before (reset for a raster, or nearly full), up to kCalls
// segments sorted one call each, then every call's result and the memory after.
#pragma once

#include "fields_segment.hpp"
#include "hls/segment/segment_arith.hpp"

bool y_sorter_top(const cig::hls::Segment<cig::hls::DefaultSegmentArith>& s,
                  cig::hls::SegmentMemory<cig::hls::DefaultSegmentArith>& m);

namespace cig {
namespace hls_tb {

struct YSorterTopCase {
  static constexpr const char* kTop = "y_sorter_top";
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
  template <class V>
  static void ports(V& v, const Input& i, const Output& o) {
    v("s", "in", "const Segment<DefaultSegmentArith>&", i.s[0]);
    v("m", "inout", "SegmentMemory<DefaultSegmentArith>&", i.memory);
    v("return", "out", "bool", o.sorted[0]);
  }
};
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
