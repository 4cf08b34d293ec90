// Testbench case of quadtree_pe_top (hls/quadtree/pe.hpp): a window, its priority-mask word and
// the raster size in, its four children (masked, covered, full, samples, window) out (seed 004).
#pragma once

#include "fields_quadtree.hpp"
#include "hls/quadtree/pe.hpp"
#include "top_case.hpp"

CIG_TB_CALL_CASE(QuadtreePeTopCase, quadtree_pe_top)
