// Testbench case of manager_visibility_top (hls/manager/visibility.hpp): a channel's setup and one
// object's bounding sphere in; the visual flag V[i], the planes the sphere is certainly outside,
// its eye-space centre and widened radius out.
#pragma once

#include "fields_manager.hpp"

void manager_visibility_top(const cig::hls::ManagerChannelSetup& setup, const cig::hls::ManagerObject& obj,
                            cig::hls::ManagerVisibility& out);

namespace cig {
namespace hls_tb {

struct ManagerVisibilityTopCase {
  static constexpr const char* kTop = "manager_visibility_top";
  struct Input {
    hls::ManagerChannelSetup setup;
    hls::ManagerObject obj;
  };
  struct Output {
    hls::ManagerVisibility out;
  };
  static void run(const Input& i, Output& o) { CIG_TB_DESIGN(manager_visibility_top)(i.setup, i.obj, o.out); }
  template <class V>
  static void ports(V& v, const Input& i, const Output& o) {
    v("setup", "in", "const ManagerChannelSetup&", i.setup);
    v("obj", "in", "const ManagerObject&", i.obj);
    v("out", "out", "ManagerVisibility&", o.out);
  }
};
template <>
struct Fields<ManagerVisibilityTopCase::Input> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.setup, "setup"), v(r.obj, "obj");
  }
};
template <>
struct Fields<ManagerVisibilityTopCase::Output> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.out, "out");
  }
};

}  // namespace hls_tb
}  // namespace cig
