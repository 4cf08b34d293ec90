// Testbench case of light_segments_top (hls/segment/light_segments.hpp): a formatted light point
// in, one whole-line segment per sample row its disc covers out, with their count (SPEC D).
#pragma once

#include "fields_segment.hpp"
#include "hls/segment/light_segments.hpp"
#include "top_case.hpp"

CIG_TB_CALL_CASE(LightSegmentsTopCase, light_segments_top)
