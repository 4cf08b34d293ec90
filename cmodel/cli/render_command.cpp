// cig render SCENE [--frame K | --frames A:B] [--channel C] [--out DIR] [--report FILE] [--ids] [--html]
//                  [--threads N] [--pipelines N] + the engine options
// Everything that can be wrong with the input is checked before anything is written.
#include "cli/render_command.hpp"
#include "cli/review_outputs.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <thread>

#include "cli/governed_frames.hpp"
#include "cli/output_plan.hpp"
#include "common/progress.hpp"
#include "generator/image_generator.hpp"
#include "image/image.hpp"
#include "scene/scene_loader.hpp"
#include "studies/frame_timing.hpp"

namespace cig::cli {

void RenderCommand::add_to(CLI::App& app) {
  threads = int(std::max(1u, std::thread::hardware_concurrency()));
  sub = app.add_subcommand("render", "render frames of a scene, one PNG per channel plus a panorama");
  sub->add_option("scene", scene_file, "scene file (JSON, scenes/README.md)")->required();
  frame_opt = sub->add_option("--frame", frame_k, "frame number (default 0)");
  sub->add_option("--frames", frames_text, "inclusive frame range A:B")->excludes(frame_opt);
  sub->add_option("--channel", channel, "render only this channel")->check(CLI::Range(0, kMaxChannelIndex));
  sub->add_option("--out", out_dir, "output directory (default out)");
  sub->add_option("--report", report_file, "report file (default DIR/report.json)");
  sub->add_option(
         "--threads", threads,
         "worker threads: over channels, and those left over split each image into strips where the engine "
         "can (segment: the video channel's lines; float: strips of rows; quadtree: the pixel colour work and the "
         "resolve; same bits) (default: cores)")
      ->check(CLI::Range(1, 64));
  sub->add_option("--pipelines", pipelines,
                  "rendering pipelines per channel (seed 000's Nc): the channel's priority list split into N "
                  "disjoint lists, each rasterised on its own thread, merged by priority (priority engines)")
      ->check(CLI::Range(1, 16));
  sub->add_option("--budget-ms", budget_ms,
                  "the frame governor: shorten the visibility range (and lower the segment processor's overload "
                  "threshold) until every stage's modelled time fits MS; the images are the governed ones, the "
                  "report says what was cut, the prediction and the PSNR against the ungoverned frame")
      ->check(CLI::Range(0.1, 1e6));
  sub->add_flag("--ids", write_ids_files, "also write per-channel id buffers (CIGIDS1)");
  sub->add_flag("--html", html,
                "also write DIR/index.html: the images, the per-frame and channel counts and times, the report, "
                "provenance (docs/review_outputs.md)");
  engine.add_to(sub);
  model_limit.add_to(sub);
  manager_unit.add_to(sub);
}

namespace {

// A channel image's file name without its extension.
std::string image_name(const Scene& scene, int frame, int channel) {
  return frame_name(frame) + "_ch" + std::to_string(channel) + "_" +
         safe_name(scene.channels[std::size_t(channel)].name);
}

// Every file the run writes into --out, known before the work (OutputPlan): per frame one PNG (and
// id buffer) per channel, and the panorama when there is more than one channel.
std::set<std::string> output_names(const Scene& scene, int a, int b, const std::vector<int>& channels, bool ids) {
  std::set<std::string> names;
  for (int frame = a; frame <= b; ++frame) {
    for (int c : channels) {
      names.insert(image_name(scene, frame, c) + ".png");
      if (ids) names.insert(image_name(scene, frame, c) + ".ids");
    }
    if (channels.size() > 1) names.insert(frame_name(frame) + "_panorama.png");
  }
  return names;
}

// One PNG (and id buffer) per channel; each channel's report names its image.
void write_channel_images(const Scene& scene, const std::string& out_dir, int frame, bool write_ids_files,
                          std::vector<ChannelOutput>& outs) {
  for (auto& co : outs) {
    const std::string base = (std::filesystem::path(out_dir) / image_name(scene, frame, co.channel)).string();
    write_png(base + ".png", co.out.image);
    if (write_ids_files) write_ids(base + ".ids", co.out.ids);
    co.report["image"] = base + ".png";
  }
}

// The panorama: channels left to right by yaw offset. Returns its path.
std::string write_panorama(const Scene& scene, const std::string& out_dir, int frame,
                           const std::vector<ChannelOutput>& outs) {
  std::vector<const ChannelOutput*> order;
  for (const auto& co : outs) order.push_back(&co);
  std::stable_sort(order.begin(), order.end(), [&](const ChannelOutput* x, const ChannelOutput* y) {
    return scene.channels[std::size_t(x->channel)].yaw_deg < scene.channels[std::size_t(y->channel)].yaw_deg;
  });
  std::vector<const Image*> parts;
  for (const auto* co : order) parts.push_back(&co->out.image);
  const std::string pano = (std::filesystem::path(out_dir) / (frame_name(frame) + "_panorama.png")).string();
  write_png(pano, concatenate_horizontally(parts));
  return pano;
}

// Every frame and channel against the engine's capacities before the first image is written
// (stages A and B only, and only when the scene could exceed them). With rendering pipelines each
// pipeline's list is held to them: each has its own frame memory and ids (seed 000).
void check_frames(const Scene& scene, int a, int b, const std::vector<int>& channels, const RasterEngine& checker,
                  VisibilityArith visibility, int pipelines) {
  if (!scene_exceeds_ids(scene)) return;
  const ImageGenerator generator(scene, {}, visibility);
  for (int frame = a; frame <= b; ++frame)
    for (int c : channels) {
      nlohmann::ordered_json unused;
      try {
        for (const ScreenFrame& part : generator.geometry_parts(frame, c, pipelines, unused)) checker.check_frame(part);
      } catch (const InputError& e) {
        throw InputError(scene.file, e.where(), e.rule());  // the scene that makes the frame
      }
    }
}

// The subobject's extent in object coordinates (after unit, scale, up and offset): where to put
// the eye and how large the model came out.
nlohmann::ordered_json bounds_report(const Subobject& s) {
  glm::dvec3 lo(0), hi(0);
  if (!s.vertices.empty()) lo = hi = s.vertices[0];
  for (const glm::dvec3& v : s.vertices) {
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  return {{"min", {lo.x, lo.y, lo.z}}, {"max", {hi.x, hi.y, hi.z}}};
}

}  // namespace

// What the priority compiler did (scene/priority_compiler.hpp), for a subobject or the scene.
nlohmann::ordered_json priority_report(const PriorityCompileSummary& p) {
  return {{"subobjects", p.subobjects},
          {"modeller_order_kept", p.ordered},
          {"kept_not_valid_from_every_eye", p.kept_not_valid},
          {"compiled", p.compiled},
          {"too_large_kept", p.too_large},
          {"polygons_before", p.polygons_before},
          {"polygons_after", p.polygons_after},
          {"splits", p.splits},
          {"slivers_dropped", p.slivers_dropped},
          {"tree_nodes", p.nodes},
          {"occlusion_groups_merged", p.groups},
          {"objects_in_merged_groups", p.grouped_objects},
          {"group_crease_angle_changed", p.group_crease_changed},
          {"cache_hits", p.cache_hits},
          {"cache_writes", p.cache_writes},
          {"ms", p.ms}};
}

namespace {

// What loading each model subobject did (scenes/README.md, "Bring your own model").
nlohmann::ordered_json models_report(const Scene& scene) {
  nlohmann::ordered_json models = nlohmann::ordered_json::array();
  for (std::size_t oi = 0; oi < scene.objects.size(); ++oi)
    for (std::size_t si = 0; si < scene.objects[oi].subobjects.size(); ++si) {
      const Subobject& s = scene.objects[oi].subobjects[si];
      if (s.model.empty()) continue;
      const ModelSummary& m = s.model_summary;
      models.push_back({{"place", "objects[" + std::to_string(oi) + "].subobjects[" + std::to_string(si) + "]"},
                        {"model", s.model},
                        {"meshes", m.meshes},
                        {"faces", m.faces},
                        {"polygons", s.polygons.size()},
                        {"triangulated_faces", m.triangulated_faces},
                        {"triangles", m.triangles},
                        {"degenerate_faces", m.degenerate_faces},
                        {"points_and_lines", m.other_primitives},
                        {"load_ms", m.load_ms},
                        {"bounds", bounds_report(s)},
                        {"priority", priority_report(s.priority)}});
    }
  return models;
}

nlohmann::ordered_json render_report(const RenderCommand& c, const Scene& scene, const EngineOptions& eo,
                                     double load_ms) {
  nlohmann::ordered_json report;
  report["command"] = "render";
  report["scene"] = c.scene_file;
  report["engine"] = c.engine.engine;
  report["snap"] = eo.snap;
  report["raster"] = scene.raster;
  report["threads"] = c.threads;
  report["pipelines"] = c.pipelines;
  report["scene_polygons"] = scene.polygon_count();
  report["scene_light_points"] = scene.light_point_count();
  report["load_ms"] = load_ms;
  report["models"] = models_report(scene);
  report["priority_compiler"] = priority_report(scene.priority);
  report["frames"] = nlohmann::ordered_json::array();
  return report;
}

// The machine's modelled frame time (studies/frame_timing.hpp, what `cig timing` prints), when the
// engine has a hardware time model.
std::optional<nlohmann::ordered_json> machine_timing(int frame, int raster, const std::vector<ChannelOutput>& outs) {
  for (const ChannelOutput& co : outs)
    if (!co.report["raster"].contains("hardware_ms")) return std::nullopt;
  return frame_timing_json(frame_timing_of(frame, raster, outs, {}));
}

}  // namespace

int RenderCommand::run() {
  // Phase 1: load and check everything.
  const EngineOptions eo = engine.options();
  const auto t_load = Clock::now();
  const Scene scene = load_scene(scene_file, model_limit.limits());
  const double load_ms = ms_since(t_load);
  int a = 0, b = 0;
  frame_range(frames_text, frame_k, frame_opt->count() > 0, scene.frame_count(), scene_file, a, b);
  const std::vector<int> channels = selected_channels(scene, channel);
  const auto probe = probe_engine(engine.engine, eo, scene, pipelines);
  refuse_engine_budget(eo);
  if (report_file.empty()) report_file = (std::filesystem::path(out_dir) / "report.json").string();
  if (html) prepare_render_html(out_dir);
  OutputPlan plan;
  plan.scene_inputs(scene);
  std::set<std::string> names = output_names(scene, a, b, channels, write_ids_files);
  if (html) names.insert("index.html");
  plan.folder(out_dir, "--out", names);
  plan.file(report_file, "--report");
  plan.check();
  check_frames(scene, a, b, channels, *probe, manager_unit.arith(), pipelines);
  std::unique_ptr<ImageGenerator> generator;
  std::unique_ptr<GovernedRun> governed;  // --budget-ms
  if (budget_ms > 0)
    governed = std::make_unique<GovernedRun>(scene, manager_unit.arith(), engine.engine, eo, budget_ms);
  else generator = std::make_unique<ImageGenerator>(scene, CullSettings{}, manager_unit.arith());
  std::filesystem::create_directories(out_dir);

  // Phase 2: the frames.
  nlohmann::ordered_json report = render_report(*this, scene, eo, load_ms);
  const auto t_all = Clock::now();
  Progress progress("cig render", b - a + 1);
  for (int frame = a; frame <= b; ++frame) {
    const auto t_frame = Clock::now();
    std::vector<ChannelOutput> outs, plain;
    FrameTiming fr_timing;  // governed: the governed frame's stages
    nlohmann::ordered_json fr;
    fr["frame"] = frame;
    if (governed) {
      const GovernedFrame g = governed->render(frame, channels, threads, pipelines, plain, outs);
      fr["governor"] = governed_json(g);
      fr_timing = g.governed;
      if (g.governed.over_budget)
        progress.note("frame " + std::to_string(frame) +
                      " is over budget after governing: " + std::to_string(g.governed.frame_ms) +
                      " ms modelled against " + std::to_string(budget_ms) + " ms (report: governor)");
    } else {
      outs = generator->render(frame, channels, engine.engine, eo, threads, pipelines);
    }
    const double render_ms = ms_since(t_frame);
    const auto t_out = Clock::now();
    write_channel_images(scene, out_dir, frame, write_ids_files, outs);
    if (outs.size() > 1) fr["panorama"] = write_panorama(scene, out_dir, frame, outs);
    fr["render_ms"] = render_ms;
    fr["output_ms"] = ms_since(t_out);
    fr["channels"] = nlohmann::ordered_json::array();
    if (governed) fr["timing"] = frame_timing_json(fr_timing);
    else if (const auto t = machine_timing(frame, scene.raster, outs)) fr["timing"] = *t;
    for (auto& co : outs) {
      progress.note(drop_warning(co.report["raster"],
                                 "frame " + std::to_string(frame) + " channel " + std::to_string(co.channel)));
      fr["channels"].push_back(std::move(co.report));
    }
    report["frames"].push_back(std::move(fr));
    progress.step("frame " + std::to_string(frame) + ": " + std::to_string(channels.size()) + " channel(s) in " +
                  std::to_string(int(render_ms)) + " ms");
  }

  // Phase 3: the report.
  report["total_ms"] = ms_since(t_all);
  write_text_file(report_file, report_text(report));
  if (html) write_render_html(out_dir, report_file, report);
  std::cout << "cig: rendered " << (b - a + 1) << " frame(s) x " << channels.size() << " channel(s) of " << scene_file
            << " to " << out_dir << " in " << int(ms_since(t_all)) << " ms (report " << report_file << ")\n";
  return 0;
}

}  // namespace cig::cli
