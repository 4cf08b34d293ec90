// Field lists (vector_io.hpp) of the scene manager's preliminary processing unit's records
// (hls/manager/records.hpp).
#pragma once

#include "hls/manager/records.hpp"
#include "vector_io.hpp"

namespace cig {
namespace hls_tb {

template <>
struct Fields<hls::ManagerChannel> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.eye, "eye"), v(r.b, "b"), v(r.tan_half_fov, "tan_half_fov"), v(r.near, "near");
  }
};
template <>
struct Fields<hls::ManagerChannelSetup> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.channel, "channel"), v(r.side_norm, "side_norm");
  }
};
template <>
struct Fields<hls::ManagerObject> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.centre, "centre"), v(r.radius, "radius");
  }
};
template <>
struct Fields<hls::ManagerVisibility> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.visible, "visible"), v(r.outside, "outside"), v(r.centre_eye, "centre_eye");
    v(r.radius_widened, "radius_widened");
  }
};

}  // namespace hls_tb
}  // namespace cig
