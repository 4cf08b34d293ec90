// Testbench case of quadtree_setup_top (hls/quadtree/setup.hpp): a formatted polygon and the
// raster size in, its edge and parameter planes as up to three root windows out (seed 004).
#pragma once

#include "fields_quadtree.hpp"
#include "hls/quadtree/setup.hpp"
#include "top_case.hpp"

CIG_TB_CALL_CASE(QuadtreeSetupTopCase, quadtree_setup_top)
