// Hand-off testbench of frame_memory_write_top: replays its golden vectors (tb_main.hpp).
#include "frame_memory_write_top.hpp"
#include "tb_main.hpp"

CIG_TB_MAIN(cig::hls_tb::FrameMemoryWriteTopCase)
