// Testbench case of overload_threshold_top (hls/segment/overload.hpp): the per-field segment counts
// by area code and a bank's capacity in, the largest area code whose polygons fit out (SPEC D).
#pragma once

#include "hls/segment/overload.hpp"
#include "vector_io.hpp"

int overload_threshold_top(const cig::hls::OverloadCounts& c, int bank_capacity);

namespace cig {
namespace hls_tb {

template <>
struct Fields<hls::OverloadCounts> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.segments, "segments");
  }
};

struct OverloadThresholdTopCase {
  static constexpr const char* kTop = "overload_threshold_top";
  struct Input {
    hls::OverloadCounts c;
    int bank_capacity = 0;
  };
  struct Output {
    int threshold = 0;
  };
  static void run(const Input& i, Output& o) {
    o.threshold = CIG_TB_DESIGN(overload_threshold_top)(i.c, i.bank_capacity);
  }
  template <class V>
  static void ports(V& v, const Input& i, const Output& o) {
    v("c", "in", "const OverloadCounts&", i.c);
    v("bank_capacity", "in", "int", i.bank_capacity);
    v("return", "out", "int", o.threshold);
  }
};
template <>
struct Fields<OverloadThresholdTopCase::Input> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.c, "c"), v(r.bank_capacity, "bank_capacity");
  }
};
template <>
struct Fields<OverloadThresholdTopCase::Output> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.threshold, "threshold");
  }
};

}  // namespace hls_tb
}  // namespace cig
