// Testbench case of quadtree_span_setup_top (hls/quadtree/span_setup.hpp): a formatted polygon, one
// of its span pieces and the raster size in; the piece's level-0 window (four edges, the polygon's
// parameter planes) and whether the polygon has any plane at all (the result) out.
#pragma once

#include "fields_quadtree.hpp"
#include "fields_span.hpp"
#include "hls/quadtree/span_setup.hpp"
#include "top_case.hpp"

CIG_TB_CALL_CASE(QuadtreeSpanSetupTopCase, quadtree_span_setup_top)
