#include "engine/engine.hpp"

#include "engine/fan_split.hpp"

namespace cig {

EngineRun RasterEngine::render(const ScreenFrame& frame) {
  const FanSplit s = fan_split_ ? split_nonplanar_polygons(frame) : FanSplit{};
  EngineRun run = render_frame(s.polygons_split > 0 ? s.frame : frame);
  if (s.polygons_split > 0) map_ids_to_source(run.out.ids, s.source);
  run.report["fan_split"] = {
      {"on", fan_split_}, {"polygons_split", s.polygons_split}, {"triangles_added", s.triangles_added}};
  return run;
}

void RasterEngine::check_frame(const ScreenFrame& frame) const {
  const FanSplit s = fan_split_ ? split_nonplanar_polygons(frame) : FanSplit{};
  check_split_frame(s.polygons_split > 0 ? s.frame : frame);
}

}  // namespace cig
