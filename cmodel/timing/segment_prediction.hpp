// The segment processor's governor (seed 001's overload protection with a time budget). Once the
// edge generator has written the frame memory, what the preprocessor will read is fixed: every
// record's area code, edge words and segments per field (the header's counts, those seed 001's
// overload counters add up per code). The governor runs the cycle model
// (timing/segment_cycle_model.hpp) on those records for a threshold T, records above T read as a
// header only, and applies the largest T whose two field passes fit the budget. Code 0 (protected
// polygons and light points) is never dropped. The prediction is the cycle model's own time for the
// records as they will be read: it differs from the frame's modelled time only by segments the
// segment memory had no room for.
#pragma once

#include <cstdint>
#include <vector>

#include "timing/segment_cycle_model.hpp"

namespace cig {

// A frame-memory record as the preprocessor will read it.
struct PlannedRecord {
  std::uint32_t edges = 0;             // edge words; 0 for a light point
  std::uint32_t segments[2] = {0, 0};  // segments it will write per field (even, odd lines)
  int code = 0;                        // area code; 0 for a light point (never dropped)
  bool light = false;
};

// The records' passes at threshold T (both fields, ns): the cycle model without the video channel.
double planned_back_ns(const std::vector<PlannedRecord>& plan, int raster_lines, int threshold,
                       const SegmentTimingParams& p);

// The largest threshold <= `ceiling` whose passes fit budget_ns (the passes grow with T: a kept
// record costs at least its header); 0 when none does (the frame is then over budget, and says so).
int governed_threshold(const std::vector<PlannedRecord>& plan, int raster_lines, double budget_ns, int ceiling,
                       const SegmentTimingParams& p);

}  // namespace cig
