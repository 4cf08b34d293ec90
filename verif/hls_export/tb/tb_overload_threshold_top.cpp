// Hand-off testbench of overload_threshold_top: replays its golden vectors (tb_main.hpp).
#include "overload_threshold_top.hpp"
#include "tb_main.hpp"

CIG_TB_MAIN(cig::hls_tb::OverloadThresholdTopCase)
