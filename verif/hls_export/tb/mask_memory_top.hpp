// Testbench case of mask_memory_top (hls/quadtree/mask_memory.hpp). The mask memory is state, so
// a vector is a sequence: the memory before, up to kCalls mask-set requests (level, x, y, child)
// one call each, then every call's result and the memory after.
#pragma once

#include "hls/quadtree/mask_memory.hpp"
#include "vector_io.hpp"

cig::hls::UInt<5> mask_memory_top(cig::hls::MaskMemory& m, cig::hls::UInt<4> level, cig::hls::UInt<10> x,
                                  cig::hls::UInt<10> y, cig::hls::UInt<2> child);

namespace cig {
namespace hls_tb {

template <>
struct Fields<hls::MaskMemory> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.word, "word");
  }
};

struct MaskMemoryTopCase {
  static constexpr const char* kTop = "mask_memory_top";
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
  template <class V>
  static void ports(V& v, const Input& i, const Output& o) {
    v("m", "inout", "MaskMemory&", i.memory);
    v("level", "in", "UInt<4>", i.level[0]);
    v("x", "in", "UInt<10>", i.x[0]);
    v("y", "in", "UInt<10>", i.y[0]);
    v("child", "in", "UInt<2>", i.child[0]);
    v("return", "out", "UInt<5>", o.result[0]);
  }
};
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
