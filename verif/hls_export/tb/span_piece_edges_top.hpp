// Testbench case of span_piece_edges_top (hls/segment/span_piece_edges.hpp): a formatted polygon,
// one of its span pieces and the raster size in; the piece's frame-memory entry (the polygon's
// header over the piece's rows, one edge on each side) out.
#pragma once

#include "fields_segment.hpp"
#include "fields_span.hpp"
#include "hls/segment/span_piece_edges.hpp"
#include "top_case.hpp"

CIG_TB_CALL_CASE(SpanPieceEdgesTopCase, span_piece_edges_top)
