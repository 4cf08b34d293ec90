#include "cli/frame_jobs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cli/cli_common.hpp"
#include "cli/output_plan.hpp"
#include "common/error.hpp"
#include "common/json_reader.hpp"
#include "frame/input_kind.hpp"
#include "registry/engine_registry.hpp"
#include "scene/scene_loader.hpp"

namespace cig::cli {

EngineOptions reference_options(const std::string& reference, int samples_per_pixel) {
  // R (the reference engine, `float`): the ground truth; R-snap: vertices snapped to the formatter
  // grid (the engines' coverage); R-snap-priority: that, with visibility by list order as the
  // engines have it.
  const std::string r = reference_engine_name();
  if (reference != r && reference != r + "-snap" && reference != r + "-snap-priority")
    throw InputError("", "--reference",
                     "'" + reference + "' is none of " + r + ", " + r + "-snap, " + r + "-snap-priority");
  EngineOptions o;
  o.snap = reference != r;
  if (reference == r + "-snap-priority") o.params["visibility"] = "priority";
  if (samples_per_pixel != 16) o.params["spp"] = std::to_string(samples_per_pixel);
  return o;
}

FrameJobs FrameJobs::load(const std::string& input, const std::string& frames_text, int frame_k, bool frame_given,
                          int channel, const SceneLimits& limits, VisibilityArith visibility,
                          const PolygonListCheck& list_check) {
  FrameJobs j;
  j.input_ = input;
  // Parsed once (the text let go): the kind, then the list or the scene from the same document.
  const nlohmann::json doc = parse_json_text(read_text_file(input), input);
  if (input_kind_of_document(doc, input) == InputKind::kPolygonList) {
    // --frame, --frames and --channel choose images of a scene; a polygon list is one image.
    if (frame_given || !frames_text.empty() || channel >= 0)
      throw InputError(input, "",
                       std::string(frame_given            ? "--frame"
                                   : !frames_text.empty() ? "--frames"
                                                          : "--channel") +
                           " applies to a scene; this input is a polygon list (one image)");
    j.list_.push_back(polygon_list_of_document(doc, input, list_check));
    j.jobs_.push_back({j.list_[0].frame, j.list_[0].channel});
    return j;
  }
  j.scene_ = std::make_unique<Scene>(scene_of_document(doc, input, limits));
  int a, b;
  frame_range(frames_text, frame_k, frame_given, j.scene_->frame_count(), input, a, b);
  if (channel >= int(j.scene_->channels.size()))
    throw InputError(input, "--channel",
                     "channel " + std::to_string(channel) + " does not exist (the scene has " +
                         std::to_string(j.scene_->channels.size()) + ")");
  for (int f = a; f <= b; ++f)
    for (int c = 0; c < int(j.scene_->channels.size()); ++c)
      if (channel < 0 || c == channel) j.jobs_.push_back({f, c});
  j.frames_ = b - a + 1;
  j.channels_ = channel < 0 ? int(j.scene_->channels.size()) : 1;
  j.generator_ = std::make_unique<ImageGenerator>(*j.scene_, CullSettings{}, visibility);
  return j;
}

PolygonListCheck FrameJobs::list_capacity(const std::string& input, const RasterEngine& engine) {
  return [&input, &engine](const ScreenFrame& head, std::size_t polygons, std::size_t light_points) {
    try {
      engine.check_raster(head.raster);
      engine.check_counts(head.frame, head.channel, polygons, light_points);
    } catch (const InputError& e) {
      if (!e.file().empty()) throw;
      throw InputError(input, e.where(), e.rule());  // the input that makes the frame
    }
  };
}

ScreenFrame FrameJobs::screen_frame(std::size_t k) const {
  if (!generator_) return list_[0];
  nlohmann::ordered_json unused;
  return generator_->geometry(jobs_[k].first, jobs_[k].second, unused);
}

std::vector<ScreenFrame> FrameJobs::screen_frame_parts(std::size_t k) const {
  if (!generator_ || pipelines_ <= 1) return {screen_frame(k)};
  nlohmann::ordered_json unused;
  return generator_->geometry_parts(jobs_[k].first, jobs_[k].second, pipelines_, unused);
}

void FrameJobs::check_capacity(const RasterEngine& engine) const {
  try {
    if (scene_) engine.check_scene(*scene_);
    if (scene_ && !scene_exceeds_ids(*scene_)) {
      if (!jobs_.empty()) engine.check_raster(scene_->raster);
      return;
    }
    for (std::size_t k = 0; k < jobs_.size(); ++k)
      for (const ScreenFrame& part : screen_frame_parts(k)) engine.check_frame(part);
  } catch (const InputError& e) {
    if (!e.file().empty()) throw;
    throw InputError(input_, e.where(), e.rule());  // the input that makes the frame
  }
}

void FrameJobs::declare_inputs(OutputPlan& plan) const {
  if (scene_) plan.scene_inputs(*scene_);
  else plan.input(input_, "the polygon list this run reads");
}

Comparison compare_run(int frame, int channel, const RasterImage& got, const RasterImage& reference) {
  return {frame,
          channel,
          compare_images(got.image, reference.image, got.ids, reference.ids),
          differing_ids(got.ids, reference.ids),
          differing_ids_off_edges(got.ids, reference.ids),
          {}};
}

void attribute_priority(Comparison& c, const RasterImage& got, const RasterImage& reference,
                        const RasterImage& priority_reference) {
  c.priority = attribute_priority(got.image, got.ids, reference.image, reference.ids, priority_reference.image,
                                  priority_reference.ids);
}

nlohmann::ordered_json comparison_json(const Comparison& c) {
  return {{"frame", c.frame},
          {"channel", c.channel},
          {"psnr", c.error.psnr()},
          {"ssim", ssim_json(c.error.ssim())},
          {"max_abs", {c.error.max_abs[0], c.error.max_abs[1], c.error.max_abs[2]}},
          {"pixels_over_2lsb", c.error.pixels_over_2lsb},
          {"ids_differ", c.ids_differ},
          {"ids_differ_off_edges", c.ids_differ_off_edges},
          {"ids_priority_vs_depth", c.priority.ids_priority_vs_depth},
          {"pixels_priority_colour", c.priority.pixels_priority_colour}};
}

std::string ssim_text(double ssim) {
  if (std::isnan(ssim)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", ssim);
  return buf;
}

nlohmann::ordered_json ssim_json(double ssim) {
  return std::isnan(ssim) ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(ssim);
}

void ComparisonTotals::add(const Comparison& c) {
  all.add(c.error);
  ++images;
  ids_differ += c.ids_differ;
  ids_differ_off_edges += c.ids_differ_off_edges;
  priority.add(c.priority);
  if (c.error.psnr() < min_psnr) {
    min_psnr = c.error.psnr();
    worst_frame = c.frame;
    worst_channel = c.channel;
  }
  if (c.error.has_ssim() && c.error.ssim() < min_ssim) {
    min_ssim = c.error.ssim();
    worst_ssim_frame = c.frame;
    worst_ssim_channel = c.channel;
  }
}

}  // namespace cig::cli
