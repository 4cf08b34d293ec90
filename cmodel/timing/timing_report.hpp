// The timing models' figures as report JSON (render, timing and sweep read them from here), in ms.
#pragma once

#include <nlohmann/json.hpp>

#include "timing/segment_cycle_model.hpp"

namespace cig {

inline nlohmann::ordered_json unit_time_json(const UnitTime& u) {
  return {{"busy_ms", u.busy_ns * 1e-6}, {"stalled_ms", u.stalled_ns * 1e-6}, {"starved_ms", u.starved_ns * 1e-6}};
}

inline nlohmann::ordered_json segment_timing_json(const SegmentFrameTiming& t) {
  nlohmann::ordered_json fields = nlohmann::ordered_json::array();
  for (const FieldTiming& f : t.field)
    fields.push_back({{"pass_ms", f.pass_ns * 1e-6},
                      {"segments", f.segments},
                      {"preprocessor", unit_time_json(f.preprocessor)},
                      {"segment_generator", unit_time_json(f.generator)},
                      {"y_sorter", unit_time_json(f.sorter)},
                      {"video_busy_ms", f.video_busy_ns * 1e-6},
                      {"underrun_lines", f.underrun_lines},
                      {"segments_not_shown", f.segments_not_shown},
                      {"worst_line_slack_ms", f.worst_line_slack_ns * 1e-6}});
  return {{"edge_generator_ms", t.front_ns * 1e-6},
          {"fields", fields},
          {"back_ms", t.back_ns * 1e-6},
          {"limiting_unit", t.limiting_unit},
          {"fits_fields", t.fits_fields},
          {"underrun_lines", t.underrun_lines}};
}

}  // namespace cig
