// Synthesis top of the scene manager's channel setup (see syn/formatter_top.cpp for why it is at
// global scope).
#include "hls/manager/channel_setup.hpp"

void manager_channel_setup_top(const cig::hls::ManagerChannel& in, cig::hls::ManagerChannelSetup& out) {
  cig::hls::manager_channel_setup_top(in, out);
}
