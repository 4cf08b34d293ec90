// Testbench case of invparam_column_top (hls/invparam/visibility.hpp, W = 64): the host's face list
// (every object's faces, set up as cmodel/invparam/face_setup.hpp sets them up), every face's value
// at one column (row -1), the column's rows, RGeps and RGnear in; each row's visible face (code and tau) out.
#pragma once

#include "fields_invparam.hpp"
#include "hls/invparam/visibility.hpp"
#include "top_case.hpp"

CIG_TB_CALL_CASE(InvparamColumnTopCase, invparam_column_top)
