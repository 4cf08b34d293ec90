// Hand-off testbench of quadtree_pe_top: replays its golden vectors (tb_main.hpp).
#include "quadtree_pe_top.hpp"
#include "tb_main.hpp"

CIG_TB_MAIN(cig::hls_tb::QuadtreePeTopCase)
