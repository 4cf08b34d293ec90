// Hand-off testbench of light_segments_top: replays its golden vectors (tb_main.hpp).
#include "light_segments_top.hpp"
#include "tb_main.hpp"

CIG_TB_MAIN(cig::hls_tb::LightSegmentsTopCase)
