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

EngineRun RasterEngine::render_parts(const std::vector<ScreenFrame>& parts) {
  std::vector<FanSplit> splits(parts.size());
  std::vector<const ScreenFrame*> split_parts;
  std::vector<std::int32_t> source;  // split polygon of the concatenated parts -> input polygon
  long polygons_split = 0, triangles_added = 0;
  std::int32_t input_offset = 0;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    if (fan_split_) splits[k] = split_nonplanar_polygons(parts[k]);
    const FanSplit& s = splits[k];
    const ScreenFrame& f = s.polygons_split > 0 ? s.frame : parts[k];
    split_parts.push_back(&f);
    for (std::size_t i = 0; i < f.polygons.size(); ++i)
      source.push_back(input_offset + (s.polygons_split > 0 ? s.source[i] : std::int32_t(i)));
    input_offset += std::int32_t(parts[k].polygons.size());
    polygons_split += s.polygons_split;
    triangles_added += s.triangles_added;
  }
  EngineRun run = render_split_parts(split_parts);
  map_ids_to_source(run.out.ids, source);
  run.report["fan_split"] = {
      {"on", fan_split_}, {"polygons_split", polygons_split}, {"triangles_added", triangles_added}};
  return run;
}

void RasterEngine::check_renders_parts() const {
  if (!renders_parts())
    throw InputError("", "--pipelines",
                     std::string("engine '") + name() +
                         "' does not merge rendering pipelines (the priority engines do: segment, segment-double, "
                         "quadtree, quadtree-double)");
}

EngineRun RasterEngine::render_split_parts(const std::vector<const ScreenFrame*>&) {
  check_renders_parts();
  return {};
}

void RasterEngine::check_frame(const ScreenFrame& frame) const {
  const FanSplit s = fan_split_ ? split_nonplanar_polygons(frame) : FanSplit{};
  check_split_frame(s.polygons_split > 0 ? s.frame : frame);
}

}  // namespace cig
