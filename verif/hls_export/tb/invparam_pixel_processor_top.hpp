// Testbench case of invparam_pixel_processor_top (hls/invparam/pixel_processor.hpp, W = 64): one
// clock of seed 002's pixel processor. Its registers carry from clock to clock, so a vector is a
// sequence over one PP of the array: the state before, up to kCalls clocks of Input and Ctrl (the
// words and the start / valid lines the PP above passed on), then every clock's outputs (Output,
// the delayed Ctrl, the VT bus, the column's end) and the state after it.
#pragma once

#include "hls/invparam/pixel_processor.hpp"
#include "top_case.hpp"

CIG_TB_PORTS(invparam_pixel_processor_top)

namespace cig {
namespace hls_tb {

template <int W>
struct Fields<hls::PpState<W>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.RGres, "RGres"), v(r.RGh, "RGh"), v(r.RGtin, "RGtin"), v(r.RGtout, "RGtout"), v(r.RGobj, "RGobj");
    v(r.RGeps, "RGeps"), v(r.RGnear, "RGnear"), v(r.RGpar, "RGpar"), v(r.RGparP, "RGparP"), v(r.RGI, "RGI"),
        v(r.Tz, "Tz");
    v(r.Ts, "Ts"), v(r.Tc, "Tc"), v(r.Tctrl, "Tctrl"), v(r.Tvalid, "Tvalid"), v(r.clock, "clock");
  }
};
template <>
struct Fields<hls::PpCtrl> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.start, "start"), v(r.valid, "valid");
  }
};
template <int W>
struct Fields<hls::VtBus<W>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.valid, "valid"), v(r.par, "par"), v(r.obj, "obj");
  }
};
template <int W>
struct Fields<hls::PpOutputs<W>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.output, "output"), v(r.ctrl, "ctrl"), v(r.vt, "vt"), v(r.ends_column, "ends_column");
  }
};

namespace invparam_pixel_processor_top_tb {

struct Case : Ports {
  static constexpr int kCalls = 48;
  static constexpr int W = hls::kPpTopWordBits;
  struct Input {
    hls::PpState<W> state;
    int calls = 0;
    hls::Word<W> input[kCalls];
    hls::PpCtrl ctrl[kCalls];
  };
  struct Output {
    hls::PpOutputs<W> result[kCalls];
    hls::PpState<W> state[kCalls];
  };
  static void run(const Input& i, Output& o) {
    hls::PpState<W> st = i.state;
    for (int k = 0; k < i.calls && k < kCalls; ++k) {
      o.result[k] = CIG_TB_DESIGN(invparam_pixel_processor_top)(st, i.input[k], i.ctrl[k]);
      o.state[k] = st;
    }
  }
};

}  // namespace invparam_pixel_processor_top_tb
using InvparamPixelProcessorTopCase = invparam_pixel_processor_top_tb::Case;
template <>
struct Fields<InvparamPixelProcessorTopCase::Input> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.state, "state"), v(r.calls, "calls"), v(r.input, "input"), v(r.ctrl, "ctrl");
  }
};
template <>
struct Fields<InvparamPixelProcessorTopCase::Output> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.result, "result"), v(r.state, "state");
  }
};

}  // namespace hls_tb
}  // namespace cig
