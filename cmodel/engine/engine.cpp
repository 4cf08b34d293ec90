#include "engine/engine.hpp"

#include "common/error.hpp"
#include "engine/fan_split.hpp"

namespace cig {

int samples_per_pixel_side_log2(const std::string& spp, int max_side_log2, const char* engine) {
  std::string known;
  for (int t = 0; t <= max_side_log2; ++t) {
    const std::string value = std::to_string(1 << (2 * t));
    if (spp == value) return t;
    known += (t ? t == max_side_log2 ? " or " : ", " : "") + value;
  }
  throw InputError("", "--engine-opt",
                   std::string("engine '") + engine + "': spp='" + spp + "' is not " + known + " (samples per pixel)");
}

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
