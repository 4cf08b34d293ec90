// Testbench case of quadtree_pe_top (hls/quadtree/pe.hpp): a window, its priority-mask word and
// the raster size in, its four children (masked, covered, full, samples, window) out (seed 004).
#pragma once

#include "fields_quadtree.hpp"
#include "hls/quadtree/quadtree_arith.hpp"

void quadtree_pe_top(const cig::hls::QuadWindow<cig::hls::DefaultQuadArith>& w, cig::hls::UInt<4> mask_word,
                     cig::hls::UInt<4> raster_log2,
                     cig::hls::QuadChild<cig::hls::DefaultQuadArith> (&children)[cig::hls::kQuadChildren]);

namespace cig {
namespace hls_tb {

struct QuadtreePeTopCase {
  static constexpr const char* kTop = "quadtree_pe_top";
  struct Input {
    hls::QuadWindow<hls::DefaultQuadArith> w;
    hls::UInt<4> mask_word, raster_log2;
  };
  struct Output {
    hls::QuadChild<hls::DefaultQuadArith> children[hls::kQuadChildren];
  };
  static void run(const Input& i, Output& o) {
    CIG_TB_DESIGN(quadtree_pe_top)(i.w, i.mask_word, i.raster_log2, o.children);
  }
  template <class V>
  static void ports(V& v, const Input& i, const Output& o) {
    v("w", "in", "const QuadWindow<DefaultQuadArith>&", i.w);
    v("mask_word", "in", "UInt<4>", i.mask_word);
    v("raster_log2", "in", "UInt<4>", i.raster_log2);
    v("children", "out", "QuadChild<DefaultQuadArith> (&)[4]", o.children);
  }
};
template <>
struct Fields<QuadtreePeTopCase::Input> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.w, "w"), v(r.mask_word, "mask_word"), v(r.raster_log2, "raster_log2");
  }
};
template <>
struct Fields<QuadtreePeTopCase::Output> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.children, "children");
  }
};

}  // namespace hls_tb
}  // namespace cig
