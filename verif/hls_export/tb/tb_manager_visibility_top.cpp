// Hand-off testbench of manager_visibility_top: replays its golden vectors (tb_main.hpp).
#include "manager_visibility_top.hpp"
#include "tb_main.hpp"

CIG_TB_MAIN(cig::hls_tb::ManagerVisibilityTopCase)
