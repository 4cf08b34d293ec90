// Hand-off testbench of segment_generator_top: replays its golden vectors (tb_main.hpp).
#include "segment_generator_top.hpp"
#include "tb_main.hpp"

CIG_TB_MAIN(cig::hls_tb::SegmentGeneratorTopCase)
