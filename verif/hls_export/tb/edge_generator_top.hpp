// Testbench case of edge_generator_top (hls/segment/edge_generator.hpp): a formatted polygon and
// the raster size in, its header and left/right edge chains out (SPEC D eq. 2, 5, 6).
#pragma once

#include "fields_segment.hpp"
#include "hls/segment/edge_generator.hpp"
#include "top_case.hpp"

CIG_TB_CALL_CASE(EdgeGeneratorTopCase, edge_generator_top)
