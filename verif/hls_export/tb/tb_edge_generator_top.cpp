// Hand-off testbench of edge_generator_top: replays its golden vectors (tb_main.hpp).
#include "edge_generator_top.hpp"
#include "tb_main.hpp"

CIG_TB_MAIN(cig::hls_tb::EdgeGeneratorTopCase)
