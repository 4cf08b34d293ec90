// The image generator, the per-frame data flow of the C model (SPEC: "a scene manager feeds a
// geometric processor, which feeds raster engines"): scene manager (A) -> geometric processor (B) ->
// a raster engine (C-F or the float reference), for every requested channel, with a report of what each
// stage did and took.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/engine.hpp"
#include "generator/frame_governor.hpp"
#include "manager/scene_manager.hpp"
#include "scene/world_database.hpp"

namespace cig {

struct ChannelOutput {
  int channel = 0;
  RasterImage out;
  nlohmann::ordered_json report;
};

class ImageGenerator {
 public:
  // The world's quadtree is built once; culling selects how the scene manager walks it (seed 003's
  // line of sight by default; the visible objects are the same whatever the method).
  // visibility: stage A's V[i] by the hls/manager kernel (the default) or its twin.
  explicit ImageGenerator(const Scene& scene, const CullSettings& culling = {},
                          VisibilityArith visibility = VisibilityArith::kKernel);
  const Scene& scene() const { return scene_; }

  // Stages A and B for one channel: the polygon list a raster engine receives.
  // governor: its visibility range for the frame (generator/frame_governor.hpp; report["governor"]).
  ScreenFrame geometry(int frame, int channel, nlohmann::ordered_json& report,
                       const FrameGovernor* governor = nullptr) const;

  // Stages A and B for one channel split among `pipelines` rendering pipelines (seed 000's Nc,
  // manager/pipeline_loading.hpp): one polygon list per pipeline, in priority order; the report
  // gives each pipeline's polygons and the load balance (max / mean). pipelines <= 1: geometry's one list.
  std::vector<ScreenFrame> geometry_parts(int frame, int channel, int pipelines, nlohmann::ordered_json& report,
                                          const FrameGovernor* governor = nullptr) const;

  // A, B and the engine for the given channels of one frame; channels run on up to `threads`
  // worker threads, each with its own engine instance. pipelines > 1: each channel's list split
  // among that many rendering pipelines, each on its own thread, merged by the engine's video
  // stage (RasterEngine::render_parts).
  std::vector<ChannelOutput> render(int frame, const std::vector<int>& channels, const std::string& engine,
                                    const EngineOptions& options, int threads, int pipelines = 1,
                                    const FrameGovernor* governor = nullptr) const;

 private:
  PriorityList manage(const ChannelView& view, nlohmann::ordered_json& report) const;
  // Stage A through the governor, when there is one: its range shortens `view`.
  PriorityList manage_governed(ChannelView& view, const FrameGovernor* governor, nlohmann::ordered_json& report) const;

  const Scene& scene_;
  WorldDatabase db_;
  std::unique_ptr<SceneQuadtree> tree_;
  ManagerOptions manager_;
  // Engines kept across frames, one per worker (engines hold multi-megabyte memories, and the
  // segment processor's frame memory alternates banks from frame to frame).
  struct EngineSlot {
    std::string name;
    std::unique_ptr<RasterEngine> engine;
  };
  mutable std::vector<EngineSlot> engines_;
};

}  // namespace cig
