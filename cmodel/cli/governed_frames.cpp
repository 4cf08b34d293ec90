#include "cli/governed_frames.hpp"

#include <algorithm>
#include <cmath>

#include "common/error.hpp"
#include "image/image_compare.hpp"
#include "registry/engine_registry.hpp"

namespace cig::cli {

namespace {

// The governor's prediction of a channel's frame: its own (A, B, edges, raster of engines without
// a governor) and the segment processor's (its field passes, timing/segment_prediction.hpp).
double predicted_channel_ms(const nlohmann::ordered_json& report) {
  double ms = report["governor"]["predicted_ms"].get<double>();
  if (report["raster"].contains("governor"))
    ms = std::max(ms, report["raster"]["governor"]["predicted_ms"].get<double>());
  return ms;
}

bool engine_takes(const std::string& engine, const char* key) {
  for (const EngineOptionSpec& o : engine_info(engine).options)
    if (o.key == key) return true;
  return false;
}
bool engine_governs_itself(const std::string& engine) { return engine_takes(engine, "budget-ms"); }

}  // namespace

FrameTiming frame_timing_of(int frame, int raster, const std::vector<ChannelOutput>& outs,
                            const MachineTimingParams& p) {
  std::vector<ChannelTiming> channels;
  for (const ChannelOutput& co : outs) channels.push_back(time_channel(co.report, raster, p));
  return time_frame(frame, channels, p);
}

void refuse_engine_budget(const EngineOptions& options) {
  const auto b = options.params.find("budget-ms");
  if (b != options.params.end() && b->second != "off")
    throw InputError("", "--engine-opt", "budget-ms is --budget-ms's (the governor sets it for the engine)");
}

GovernedRun::GovernedRun(const Scene& scene, VisibilityArith visibility, const std::string& engine,
                         const EngineOptions& options, double budget_ms)
    : scene_(scene),
      engine_(engine),
      plain_options_(options),
      governed_options_(options),
      plain_(scene, {}, visibility),
      governed_(scene, {}, visibility),
      governor_(budget_ms, engine_governs_itself(engine), int(scene.channels.size())) {
  refuse_engine_budget(options);
  params_.budget_ms = budget_ms;
  if (engine_governs_itself(engine)) governed_options_.params["budget-ms"] = std::to_string(budget_ms);
  // Seed 004's start window at each polygon's bounding box: the same image in fewer child tests,
  // the cheapest degradation there is (it costs nothing), unless the command line chose one.
  if (engine_takes(engine, "start") && !options.params.count("start")) governed_options_.params["start"] = "bbox";
}

GovernedFrame GovernedRun::render(int frame, const std::vector<int>& channels, int threads, int pipelines,
                                  std::vector<ChannelOutput>& plain, std::vector<ChannelOutput>& governed) {
  plain = plain_.render(frame, channels, engine_, plain_options_, threads, pipelines);
  governed = governed_.render(frame, channels, engine_, governed_options_, threads, pipelines, &governor_);
  GovernedFrame g;
  g.ungoverned = frame_timing_of(frame, scene_.raster, plain, params_);
  g.governed = frame_timing_of(frame, scene_.raster, governed, params_);
  for (std::size_t k = 0; k < governed.size(); ++k) {
    const nlohmann::ordered_json& r = governed[k].report;
    const ChannelTiming& t = g.governed.channels[k];
    const nlohmann::ordered_json& gov = r["governor"];
    governor_.learn(governed[k].channel, FrameGovernor::decision_of(gov), t.stages.a_ms, t.geometry_ms,
                    t.edge_generator_ms, t.stages.raster_ms);
    g.predicted_ms = std::max(g.predicted_ms, predicted_channel_ms(r));
    g.psnr = std::min(g.psnr, compare_images(governed[k].out.image, plain[k].out.image).psnr());
    g.objects_cut += gov["objects_cut"].get<long>();
    if (gov["range_cut"].get<bool>())
      g.range = g.range > 0 ? std::min(g.range, gov["range"].get<double>()) : gov["range"].get<double>();
    if (r["raster"].contains("governor")) g.polygons_dropped += r["raster"]["governor"]["polygons_dropped"].get<long>();
  }
  g.prediction_error = g.governed.frame_ms > 0 ? g.predicted_ms / g.governed.frame_ms - 1 : 0;
  return g;
}

nlohmann::ordered_json governed_json(const GovernedFrame& g) {
  return {{"frame", g.governed.frame},
          {"ungoverned", frame_timing_json(g.ungoverned)},
          {"governed", frame_timing_json(g.governed)},
          {"predicted_ms", g.predicted_ms},
          {"prediction_error", g.prediction_error},
          {"range", g.range},
          {"objects_cut", g.objects_cut},
          {"polygons_dropped_by_threshold", g.polygons_dropped},
          {"psnr_against_ungoverned", g.psnr}};
}

nlohmann::ordered_json governor_summary(const std::vector<GovernedFrame>& frames) {
  std::vector<double> error, psnr;
  for (const GovernedFrame& g : frames) {
    error.push_back(std::abs(g.prediction_error));
    psnr.push_back(g.psnr);
  }
  const double psnr_min = psnr.empty() ? 99 : *std::min_element(psnr.begin(), psnr.end());
  return {{"prediction_error_abs", {{"p50", percentile(error, 50)}, {"max", percentile(error, 100)}}},
          {"psnr_against_ungoverned", {{"p50", percentile(psnr, 50)}, {"min", psnr_min}}}};
}

}  // namespace cig::cli
