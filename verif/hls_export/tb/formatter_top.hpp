// Testbench case of formatter_top (hls/formatter/formatter.hpp): one raw primitive in, one
// formatted primitive out (SPEC C eq. 1, 3, 4).
#pragma once

#include "fields_formatter.hpp"

void formatter_top(const cig::hls::RawPrimitive& in, cig::hls::FormattedPrimitive& out);

namespace cig {
namespace hls_tb {

struct FormatterTopCase {
  static constexpr const char* kTop = "formatter_top";
  struct Input {
    hls::RawPrimitive in;
  };
  struct Output {
    hls::FormattedPrimitive out;
  };
  static void run(const Input& i, Output& o) { CIG_TB_DESIGN(formatter_top)(i.in, o.out); }
  template <class V>
  static void ports(V& v, const Input& i, const Output& o) {
    v("in", "in", "const RawPrimitive&", i.in);
    v("out", "out", "FormattedPrimitive&", o.out);
  }
};
template <>
struct Fields<FormatterTopCase::Input> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.in, "in");
  }
};
template <>
struct Fields<FormatterTopCase::Output> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.out, "out");
  }
};

}  // namespace hls_tb
}  // namespace cig
