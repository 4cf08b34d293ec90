// Hand-off testbench of video_channel_top: replays its golden vectors (tb_main.hpp).
#include "tb_main.hpp"
#include "video_channel_top.hpp"

CIG_TB_MAIN(cig::hls_tb::VideoChannelTopCase)
