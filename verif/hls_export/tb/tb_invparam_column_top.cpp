// Hand-off testbench of invparam_column_top: replays its golden vectors (tb_main.hpp).
#include "invparam_column_top.hpp"
#include "tb_main.hpp"

CIG_TB_MAIN(cig::hls_tb::InvparamColumnTopCase)
