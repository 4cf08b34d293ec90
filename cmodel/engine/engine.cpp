#include "engine/engine.hpp"

#include "common/error.hpp"
#include "engine/fan_split.hpp"
#include "formatter/formatter_twin.hpp"
#include "hls/formatter/sample_lattice.hpp"

namespace cig {

const std::vector<DropKind>& RasterEngine::drop_kinds() const {
  static const std::vector<DropKind> kNone;
  return kNone;
}

void RasterEngine::complete_dropped(nlohmann::ordered_json& report) const {
  const nlohmann::ordered_json given =
      report.contains("dropped") ? report["dropped"] : nlohmann::ordered_json::object();
  nlohmann::ordered_json dropped = nlohmann::ordered_json::object();
  for (const DropKind& k : drop_kinds()) dropped[k.key] = given.value(k.key, 0L);
  for (auto it = given.begin(); it != given.end(); ++it)
    if (!dropped.contains(it.key())) dropped[it.key()] = it.value();
  report["dropped"] = dropped;
}

void RasterEngine::check_formatter_grid(int raster) const {
  if (subpixel_bits_ < 0) return;
  const int grid_bits = hls::raster_log2_of(raster) + subpixel_bits_;
  if (grid_bits > kSeedGridBits)
    throw InputError("", "--engine-opt",
                     std::string("engine '") + name() + "': subpixel=" + std::to_string(subpixel_bits_) + " at " +
                         std::to_string(raster) + " lines needs a " + std::to_string(grid_bits) +
                         "-bit formatter grid; eq. 1's is " + std::to_string(kSeedGridBits) +
                         " bits (X = 2048 Xs + 2047), so this engine takes subpixel <= " +
                         std::to_string(kSeedGridBits - hls::raster_log2_of(raster)) +
                         " here (the float reference takes finer grids with --snap)");
}

const ScreenFrame& RasterEngine::on_formatter_grid(const ScreenFrame& frame, ScreenFrame& snapped) const {
  if (subpixel_bits_ < 0) return frame;
  check_formatter_grid(frame.raster);
  snapped = snap_to_formatter_grid(frame, hls::raster_log2_of(frame.raster) + subpixel_bits_);
  return snapped;
}

// The fan split decides on the positions as given (as without a grid setting), then the pieces
// are snapped: a triangle of the fan keeps its polygon's vertices, so it snaps to the same points.
const ScreenFrame& RasterEngine::engine_frame(const ScreenFrame& frame, FanSplit& split, ScreenFrame& snapped) const {
  split = fan_split_ ? split_nonplanar_polygons(frame) : FanSplit{};
  return on_formatter_grid(split.polygons_split > 0 ? split.frame : frame, snapped);
}

EngineRun RasterEngine::render(const ScreenFrame& frame) {
  FanSplit s;
  ScreenFrame snapped;
  EngineRun run = render_frame(engine_frame(frame, s, snapped));
  if (s.polygons_split > 0) map_ids_to_source(run.out.ids, s.source);
  run.report["fan_split"] = {
      {"on", fan_split_}, {"polygons_split", s.polygons_split}, {"triangles_added", s.triangles_added}};
  if (subpixel_bits_ >= 0)
    run.report["formatter_grid"] = {{"subpixel_bits", subpixel_bits_},
                                    {"grid_bits", hls::raster_log2_of(frame.raster) + subpixel_bits_}};
  complete_dropped(run.report);
  return run;
}

EngineRun RasterEngine::render_parts(const std::vector<ScreenFrame>& parts) {
  std::vector<FanSplit> splits(parts.size());
  std::vector<const ScreenFrame*> split_parts;
  std::vector<std::int32_t> source;  // split polygon of the concatenated parts -> input polygon
  long polygons_split = 0, triangles_added = 0;
  std::int32_t input_offset = 0;
  std::vector<ScreenFrame> snapped(parts.size());
  for (std::size_t k = 0; k < parts.size(); ++k) {
    if (fan_split_) splits[k] = split_nonplanar_polygons(parts[k]);
    const FanSplit& s = splits[k];
    const ScreenFrame& f = on_formatter_grid(s.polygons_split > 0 ? s.frame : parts[k], snapped[k]);
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
  complete_dropped(run.report);
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
  check_formatter_grid(frame.raster);
  const FanSplit s = fan_split_ ? split_nonplanar_polygons(frame) : FanSplit{};
  check_split_frame(s.polygons_split > 0 ? s.frame : frame);
}

}  // namespace cig
