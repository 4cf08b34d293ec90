// Hand-off testbench of quadtree_span_setup_top: replays its golden vectors (tb_main.hpp).
#include "quadtree_span_setup_top.hpp"
#include "tb_main.hpp"

CIG_TB_MAIN(cig::hls_tb::QuadtreeSpanSetupTopCase)
