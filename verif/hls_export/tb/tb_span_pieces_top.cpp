// Hand-off testbench of span_pieces_top: replays its golden vectors (tb_main.hpp).
#include "span_pieces_top.hpp"
#include "tb_main.hpp"

CIG_TB_MAIN(cig::hls_tb::SpanPiecesTopCase)
