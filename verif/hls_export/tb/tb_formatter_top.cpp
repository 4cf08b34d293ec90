// Hand-off testbench of formatter_top: replays its golden vectors (tb_main.hpp).
#include "formatter_top.hpp"
#include "tb_main.hpp"

CIG_TB_MAIN(cig::hls_tb::FormatterTopCase)
