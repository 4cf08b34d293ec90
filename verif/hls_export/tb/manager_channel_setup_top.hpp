// Testbench case of manager_channel_setup_top (hls/manager/channel_setup.hpp): one channel (eye, B,
// tan(fov/2), near) in, the channel with its side planes' normal length sqrt(1 + t^2) rounded up out.
#pragma once

#include "fields_manager.hpp"

void manager_channel_setup_top(const cig::hls::ManagerChannel& in, cig::hls::ManagerChannelSetup& out);

namespace cig {
namespace hls_tb {

struct ManagerChannelSetupTopCase {
  static constexpr const char* kTop = "manager_channel_setup_top";
  struct Input {
    hls::ManagerChannel in;
  };
  struct Output {
    hls::ManagerChannelSetup out;
  };
  static void run(const Input& i, Output& o) { CIG_TB_DESIGN(manager_channel_setup_top)(i.in, o.out); }
  template <class V>
  static void ports(V& v, const Input& i, const Output& o) {
    v("in", "in", "const ManagerChannel&", i.in);
    v("out", "out", "ManagerChannelSetup&", o.out);
  }
};
template <>
struct Fields<ManagerChannelSetupTopCase::Input> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.in, "in");
  }
};
template <>
struct Fields<ManagerChannelSetupTopCase::Output> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.out, "out");
  }
};

}  // namespace hls_tb
}  // namespace cig
