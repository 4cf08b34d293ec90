// Testbench case of quadtree_setup_top (hls/quadtree/setup.hpp): a formatted polygon and the
// raster size in, its edge and parameter planes as up to three root windows out (seed 004).
#pragma once

#include "fields_quadtree.hpp"
#include "hls/quadtree/quadtree_arith.hpp"

void quadtree_setup_top(const cig::hls::FormattedPrimitive& f, cig::hls::UInt<4> raster_log2,
                        cig::hls::QuadSetup<cig::hls::DefaultQuadArith>& out);

namespace cig {
namespace hls_tb {

struct QuadtreeSetupTopCase {
  static constexpr const char* kTop = "quadtree_setup_top";
  struct Input {
    hls::FormattedPrimitive f;
    hls::UInt<4> raster_log2;
  };
  struct Output {
    hls::QuadSetup<hls::DefaultQuadArith> out;
  };
  static void run(const Input& i, Output& o) { CIG_TB_DESIGN(quadtree_setup_top)(i.f, i.raster_log2, o.out); }
  template <class V>
  static void ports(V& v, const Input& i, const Output& o) {
    v("f", "in", "const FormattedPrimitive&", i.f);
    v("raster_log2", "in", "UInt<4>", i.raster_log2);
    v("out", "out", "QuadSetup<DefaultQuadArith>&", o.out);
  }
};
template <>
struct Fields<QuadtreeSetupTopCase::Input> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.f, "f"), v(r.raster_log2, "raster_log2");
  }
};
template <>
struct Fields<QuadtreeSetupTopCase::Output> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.out, "out");
  }
};

}  // namespace hls_tb
}  // namespace cig
