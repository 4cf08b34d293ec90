// Hand-off testbench of y_sorter_top: replays its golden vectors (tb_main.hpp).
#include "tb_main.hpp"
#include "y_sorter_top.hpp"

CIG_TB_MAIN(cig::hls_tb::YSorterTopCase)
