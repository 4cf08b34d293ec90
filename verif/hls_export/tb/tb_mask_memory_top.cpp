// Hand-off testbench of mask_memory_top: replays its golden vectors (tb_main.hpp).
#include "mask_memory_top.hpp"
#include "tb_main.hpp"

CIG_TB_MAIN(cig::hls_tb::MaskMemoryTopCase)
