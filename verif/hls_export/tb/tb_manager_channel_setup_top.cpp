// Hand-off testbench of manager_channel_setup_top: replays its golden vectors (tb_main.hpp).
#include "manager_channel_setup_top.hpp"
#include "tb_main.hpp"

CIG_TB_MAIN(cig::hls_tb::ManagerChannelSetupTopCase)
