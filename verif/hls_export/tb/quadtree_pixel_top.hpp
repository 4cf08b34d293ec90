// Testbench case of quadtree_pixel_top (hls/quadtree/pixel_processor.hpp). The pixel's state
// (owned samples, colour sums) carries from call to call, so a vector is a sequence over one pixel:
// the frame's fog and background tables, the state before, up to kCalls pixel-level windows (in
// priority order, with their covered samples and the lights at the pixel), then every call's
// result and the state after it.
#pragma once

#include "fields_quadtree.hpp"
#include "hls/quadtree/pixel_processor.hpp"
#include "hls/quadtree/quadtree_arith.hpp"
#include "top_case.hpp"

CIG_TB_PORTS(quadtree_pixel_top)

namespace cig {
namespace hls_tb {

template <class P>
struct Fields<hls::QuadPixelState<P>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.owned, "owned"), v(r.sum, "sum");
  }
};
template <class P>
struct Fields<hls::QuadLightCover<P>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.mask, "mask"), v(r.priority, "priority"), v(r.colour, "colour");
  }
};
template <class P>
struct Fields<hls::QuadPixelTables<P>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.fog, "fog"), v(r.fog_colour, "fog_colour"), v(r.background, "background");
  }
};

namespace quadtree_pixel_top_tb {

struct Case : Ports {
  static constexpr int kCalls = 24;
  using P = hls::DefaultQuadArith;
  struct Input {
    hls::QuadPixelTables<P> tables;
    hls::QuadLightCover<P> lights;
    hls::QuadPixelState<P> state;
    int calls = 0;
    hls::QuadWindow<P> px[kCalls];
    hls::PixelSampleMask samples[kCalls];
  };
  struct Output {
    hls::PixelSampleMask result[kCalls];
    hls::QuadPixelState<P> state[kCalls];
  };
  static void run(const Input& i, Output& o) {
    hls::QuadPixelState<P> st = i.state;
    for (int k = 0; k < i.calls && k < kCalls; ++k) {
      o.result[k] = CIG_TB_DESIGN(quadtree_pixel_top)(i.px[k], i.samples[k], i.tables, i.lights, st);
      o.state[k] = st;
    }
  }
};

}  // namespace quadtree_pixel_top_tb
using QuadtreePixelTopCase = quadtree_pixel_top_tb::Case;
template <>
struct Fields<QuadtreePixelTopCase::Input> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.tables, "tables"), v(r.lights, "lights"), v(r.state, "state"), v(r.calls, "calls"), v(r.px, "px");
    v(r.samples, "samples");
  }
};
template <>
struct Fields<QuadtreePixelTopCase::Output> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.result, "result"), v(r.state, "state");
  }
};

}  // namespace hls_tb
}  // namespace cig
