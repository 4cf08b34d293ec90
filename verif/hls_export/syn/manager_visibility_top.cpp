// Synthesis top of the scene manager's preliminary processing unit (see syn/formatter_top.cpp for
// why it is at global scope).
#include "hls/manager/visibility.hpp"

void manager_visibility_top(const cig::hls::ManagerChannelSetup& setup, const cig::hls::ManagerObject& obj,
                            cig::hls::ManagerVisibility& out) {
  cig::hls::manager_visibility_top(setup, obj, out);
}
