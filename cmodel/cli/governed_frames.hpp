// A run with the frame governor (`--budget-ms` of cig render and cig timing): every frame drawn
// twice by two image generators, without and with the governor (generator/frame_governor.hpp, and
// the engine's own budget-ms where it takes one: the segment processor's threshold), the governor
// learning from each governed frame's modelled stages (studies/frame_timing.hpp); per frame the
// prediction against the model and the image cost, PSNR of the governed image against the other.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "generator/frame_governor.hpp"
#include "generator/image_generator.hpp"
#include "studies/frame_timing.hpp"

namespace cig::cli {

struct GovernedFrame {
  FrameTiming ungoverned, governed;
  double predicted_ms = 0, prediction_error = 0;  // the governor's frame time against the model's
  double psnr = 99;                               // the governed image against the ungoverned, worst channel
  long objects_cut = 0, polygons_dropped = 0;
  double range = 0;  // the shortest range a channel was given (m); 0: none cut
};

class GovernedRun {
 public:
  // InputError when the engine options set budget-ms themselves.
  GovernedRun(const Scene& scene, VisibilityArith visibility, const std::string& engine, const EngineOptions& options,
              double budget_ms);
  // The frame's channels, ungoverned (plain) and governed, and what the governor did.
  GovernedFrame render(int frame, const std::vector<int>& channels, int threads, int pipelines,
                       std::vector<ChannelOutput>& plain, std::vector<ChannelOutput>& governed);

 private:
  const Scene& scene_;
  std::string engine_;
  EngineOptions plain_options_, governed_options_;
  MachineTimingParams params_;
  ImageGenerator plain_, governed_;
  FrameGovernor governor_;
};

// A frame's machine timing from its channels' reports (studies/frame_timing.hpp).
FrameTiming frame_timing_of(int frame, int raster, const std::vector<ChannelOutput>& outs,
                            const MachineTimingParams& p);

// --engine-opt budget-ms (other than off, the engine's default) is --budget-ms's to set on render
// and timing (InputError).
void refuse_engine_budget(const EngineOptions& options);

nlohmann::ordered_json governed_json(const GovernedFrame& g);
// The figures a governed run adds: prediction error and image cost (p50, max / min).
nlohmann::ordered_json governor_summary(const std::vector<GovernedFrame>& frames);

}  // namespace cig::cli
