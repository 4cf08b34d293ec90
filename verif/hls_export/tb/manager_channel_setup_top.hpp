// Testbench case of manager_channel_setup_top (hls/manager/channel_setup.hpp): one channel (eye, B,
// tan(fov/2), near) in, the channel with its side planes' normal length sqrt(1 + t^2) rounded up out.
#pragma once

#include "fields_manager.hpp"
#include "hls/manager/channel_setup.hpp"
#include "top_case.hpp"

CIG_TB_CALL_CASE(ManagerChannelSetupTopCase, manager_channel_setup_top)
