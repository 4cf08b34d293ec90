#include "engine/engine.hpp"

#include <algorithm>

#include "engine/fan_split.hpp"

namespace cig {

namespace {

bool needs_split(bool on, const ScreenFrame& frame) {
  return on && !std::all_of(frame.polygons.begin(), frame.polygons.end(), attributes_planar);
}

}  // namespace

EngineRun RasterEngine::render(const ScreenFrame& frame) {
  EngineRun run;
  long split = 0, added = 0;
  if (needs_split(fan_split_, frame)) {
    const FanSplit s = split_nonplanar_polygons(frame);
    run = render_frame(s.frame);
    map_ids_to_source(run.out.ids, s.source);
    split = s.polygons_split;
    added = s.triangles_added;
  } else {
    run = render_frame(frame);
  }
  run.report["fan_split"] = {{"on", fan_split_}, {"polygons_split", split}, {"triangles_added", added}};
  return run;
}

void RasterEngine::check_frame(const ScreenFrame& frame) const {
  if (needs_split(fan_split_, frame)) check_split_frame(split_nonplanar_polygons(frame).frame);
  else check_split_frame(frame);
}

}  // namespace cig
