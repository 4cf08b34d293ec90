// Hand-off testbench of invparam_pixel_processor_top: replays its golden vectors (tb_main.hpp).
#include "invparam_pixel_processor_top.hpp"
#include "tb_main.hpp"

CIG_TB_MAIN(cig::hls_tb::InvparamPixelProcessorTopCase)
