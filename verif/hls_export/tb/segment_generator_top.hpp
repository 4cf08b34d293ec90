// Testbench case of segment_generator_top (hls/segment/segment_generator.hpp): a polygon's edge
// chains in, one segment per raster line it crosses out, with their count (SPEC D).
#pragma once

#include "fields_segment.hpp"
#include "hls/segment/segment_generator.hpp"
#include "top_case.hpp"

CIG_TB_CALL_CASE(SegmentGeneratorTopCase, segment_generator_top)
