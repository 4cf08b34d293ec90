// Testbench case of mask_memory_top (hls/quadtree/mask_memory.hpp). The mask memory is state, so
// a vector is a sequence: the memory before, up to kCalls mask-set requests (level, x, y, child)
// one call each, then every call's result and the memory after.
#pragma once

#include "hls/quadtree/mask_memory.hpp"
#include "top_case.hpp"

CIG_TB_PORTS(mask_memory_top)

namespace cig {
namespace hls_tb {

template <>
struct Fields<hls::MaskMemory> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.word, "word");
  }
};

namespace mask_memory_top_tb {

struct Case : Ports {
  static constexpr int kCalls = 96;
  struct Input {
    hls::MaskMemory memory;
    int calls = 0;
    hls::UInt<4> level[kCalls];
    hls::UInt<10> x[kCalls], y[kCalls];
    hls::UInt<2> child[kCalls];
  };
  struct Output {
    hls::UInt<5> result[kCalls];
    hls::MaskMemory memory;
  };
  static void run(const Input& i, Output& o) {
    o.memory = i.memory;
    for (int k = 0; k < i.calls && k < kCalls; ++k)
      o.result[k] = CIG_TB_DESIGN(mask_memory_top)(o.memory, i.level[k], i.x[k], i.y[k], i.child[k]);
  }
};

}  // namespace mask_memory_top_tb
using MaskMemoryTopCase = mask_memory_top_tb::Case;
template <>
struct Fields<MaskMemoryTopCase::Input> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.memory, "memory"), v(r.calls, "calls"), v(r.level, "level"), v(r.x, "x"), v(r.y, "y");
    v(r.child, "child");
  }
};
template <>
struct Fields<MaskMemoryTopCase::Output> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.result, "result"), v(r.memory, "memory");
  }
};

}  // namespace hls_tb
}  // namespace cig
