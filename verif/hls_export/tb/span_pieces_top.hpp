// Testbench case of span_pieces_top (hls/formatter/span_pieces.hpp): a formatted polygon and the
// raster size in; whether it is convex, or its span pieces (the crossing rule's coverage as
// disjoint pieces between two polygon edges over a range of sample rows) out.
#pragma once

#include "fields_span.hpp"
#include "hls/formatter/span_pieces.hpp"
#include "top_case.hpp"

CIG_TB_CALL_CASE(SpanPiecesTopCase, span_pieces_top)
