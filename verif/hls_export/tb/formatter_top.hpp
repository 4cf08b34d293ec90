// Testbench case of formatter_top (hls/formatter/formatter.hpp): one raw primitive in, one
// formatted primitive out (SPEC C eq. 1, 3, 4).
#pragma once

#include "fields_formatter.hpp"
#include "hls/formatter/formatter.hpp"
#include "top_case.hpp"

CIG_TB_CALL_CASE(FormatterTopCase, formatter_top)
