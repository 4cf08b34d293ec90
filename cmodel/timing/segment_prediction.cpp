#include "timing/segment_prediction.hpp"

namespace cig {

double planned_back_ns(const std::vector<PlannedRecord>& plan, int raster_lines, int threshold,
                       const SegmentTimingParams& p) {
  SegmentLoad load;
  load.raster_lines = raster_lines;
  load.line_segments.assign(std::size_t(raster_lines), 0);  // no video: only the passes are asked
  load.line_last_item.assign(std::size_t(raster_lines), -1);
  load.items.reserve(plan.size());
  for (const PlannedRecord& r : plan) {
    SegmentLoadItem item;
    item.edges = r.edges;
    item.light = r.light;
    item.dropped = !r.light && r.code > threshold;
    for (int f = 0; f < 2; ++f) item.segments[f] = item.dropped ? 0 : r.segments[f];
    load.items.push_back(item);
  }
  return time_segment_frame({load}, p).back_ns;
}

int governed_threshold(const std::vector<PlannedRecord>& plan, int raster_lines, double budget_ns, int ceiling,
                       const SegmentTimingParams& p) {
  if (planned_back_ns(plan, raster_lines, ceiling, p) <= budget_ns) return ceiling;
  int lo = 0, hi = ceiling;  // fits(lo) or lo = 0; not fits(hi)
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    (planned_back_ns(plan, raster_lines, mid, p) <= budget_ns ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace cig
