// Testbench case of invparam_column_top (hls/invparam/visibility.hpp, W = 64): the host's face list
// (every object's faces, set up as cmodel/invparam/face_setup.hpp sets them up), every face's value
// at one column (row -1), the column's rows, RGeps and RGnear in; each row's visible face (code and tau) out.
#pragma once

#include "fields_invparam.hpp"

void invparam_column_top(const cig::hls::InvparamFaces<cig::hls::kDefaultWordBits>& faces,
                         const cig::hls::InvparamColumn<cig::hls::kDefaultWordBits>& column, int rows,
                         const cig::hls::Word<cig::hls::kDefaultWordBits>& eps,
                         const cig::hls::Word<cig::hls::kDefaultWordBits>& tau_near,
                         cig::hls::InvparamSample<cig::hls::kDefaultWordBits> out[cig::hls::kMaxSamplesPerColumn]);

namespace cig {
namespace hls_tb {

struct InvparamColumnTopCase {
  static constexpr const char* kTop = "invparam_column_top";
  static constexpr int W = hls::kDefaultWordBits;
  struct Input {
    hls::InvparamFaces<W> faces;
    hls::InvparamColumn<W> column;
    int rows = 0;
    hls::Word<W> eps;
    hls::Word<W> tau_near;
  };
  struct Output {
    hls::InvparamSample<W> out[hls::kMaxSamplesPerColumn];
  };
  static void run(const Input& i, Output& o) {
    CIG_TB_DESIGN(invparam_column_top)(i.faces, i.column, i.rows, i.eps, i.tau_near, o.out);
  }
  template <class V>
  static void ports(V& v, const Input& i, const Output& o) {
    v("faces", "in", "const InvparamFaces<64>&", i.faces);
    v("column", "in", "const InvparamColumn<64>&", i.column);
    v("rows", "in", "int", i.rows);
    v("eps", "in", "const Word<64>&", i.eps);
    v("tau_near", "in", "const Word<64>&", i.tau_near);
    v("out", "out", "InvparamSample<64>[kMaxSamplesPerColumn]", o.out);
  }
};
template <>
struct Fields<InvparamColumnTopCase::Input> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.faces, "faces"), v(r.column, "column"), v(r.rows, "rows"), v(r.eps, "eps"), v(r.tau_near, "tau_near");
  }
};
template <>
struct Fields<InvparamColumnTopCase::Output> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.out, "out");
  }
};

}  // namespace hls_tb
}  // namespace cig
