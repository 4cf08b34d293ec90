// Field lists (vector_io.hpp) of stage F's column records: the host's face setup
// (hls/invparam/records.hpp) and the face list, column values and sample results of the column
// kernel (hls/invparam/visibility.hpp). Words (Word<W> = WideInt<W>) are vector_io.hpp's wide leaves.
#pragma once

#include "hls/invparam/records.hpp"
#include "hls/invparam/visibility.hpp"
#include "vector_io.hpp"

namespace cig {
namespace hls_tb {

template <int W>
struct Fields<hls::FaceSetup<W>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.az, "az"), v(r.as, "as"), v(r.start, "start"), v(r.step_x, "step_x"), v(r.step_y, "step_y");
    v(r.colour, "colour");
  }
};
template <int W>
struct Fields<hls::InvparamFaces<W>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.face, "face"), v(r.object_faces, "object_faces"), v(r.objects, "objects");
  }
};
template <int W>
struct Fields<hls::InvparamColumn<W>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.value, "value");
  }
};
template <int W>
struct Fields<hls::InvparamSample<W>> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.hit, "hit"), v(r.code, "code"), v(r.tau, "tau");
  }
};

}  // namespace hls_tb
}  // namespace cig
