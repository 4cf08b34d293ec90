// What `cig compare` and `cig sweep` share: the images they work on (a polygon list, or a scene's
// frames x channels through stages A and B), the reference they compare with, and the comparison
// of one image (PSNR, SSIM, maximum absolute error, pixels off by more than 2 LSB, ids) with its
// totals.
#pragma once

#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "engine/engine.hpp"
#include "generator/image_generator.hpp"
#include "image/image_compare.hpp"
#include "scene/scene_loader.hpp"

namespace cig::cli {

class OutputPlan;

// --reference float | float-snap | float-snap-priority: the float engine, unsnapped or snapped to
// the formatter grid, z-buffered or by list order; --reference-spp: its samples per pixel (16 as
// the engines, or 64 / 256 for a ground truth finer than any engine).
EngineOptions reference_options(const std::string& reference, int samples_per_pixel = 16);
// Adds --reference-spp to a command.
inline void add_reference_spp(CLI::App* app, int& spp) {
  app->add_option("--reference-spp", spp, "reference samples per pixel: 1, 4, 16 (default), 64, 256")
      ->check(CLI::IsMember({1, 4, 16, 64, 256}));
}

// The images of an input: a polygon list is one image; a scene gives frames A..B (--frames A:B,
// --frame K, or frame 0) x channels (all, or --channel C). Checked when loaded (InputError).
class FrameJobs {
 public:
  // `list_check`: a polygon list's capacity check on its counts, before its polygons are read.
  static FrameJobs load(const std::string& input, const std::string& frames_text, int frame_k, bool frame_given,
                        int channel, const SceneLimits& limits = {},
                        VisibilityArith visibility = VisibilityArith::kKernel, const PolygonListCheck& list_check = {});
  // The engine's raster and capacity on a polygon list's counts (RasterEngine::check_counts),
  // naming `input`: FrameJobs::load's `list_check`.
  static PolygonListCheck list_capacity(const std::string& input, const RasterEngine& engine);
  std::size_t size() const { return jobs_.size(); }
  int frame(std::size_t k) const { return jobs_[k].first; }
  int channel(std::size_t k) const { return jobs_[k].second; }
  int frames() const { return frames_; }      // distinct frames
  int channels() const { return channels_; }  // channels per frame
  // The polygon list the engines receive for image k (stages A and B for a scene; thread-safe).
  ScreenFrame screen_frame(std::size_t k) const;
  // With rendering pipelines (set_pipelines, scenes only): image k's list split among them.
  void set_pipelines(int n) { pipelines_ = n; }
  bool is_scene() const { return generator_ != nullptr; }
  int pipelines() const { return pipelines_; }
  std::vector<ScreenFrame> screen_frame_parts(std::size_t k) const;
  // Every image against the engine's capacities before any work (RasterEngine::check_frame). A
  // scene whose polygons and lights all fit is not run through stages A and B for it.
  void check_capacity(const RasterEngine& engine) const;
  // The files the images come from (the polygon list, or the scene and its OBJ models).
  void declare_inputs(OutputPlan& plan) const;

 private:
  std::string input_;              // the file, for errors
  std::vector<ScreenFrame> list_;  // polygon-list input
  std::unique_ptr<Scene> scene_;
  std::unique_ptr<ImageGenerator> generator_;
  std::vector<std::pair<int, int>> jobs_;  // (frame, channel)
  int frames_ = 1, channels_ = 1;
  int pipelines_ = 1;
};

// One image against the reference.
struct Comparison {
  int frame = 0, channel = 0;
  ImageError error;
  long ids_differ = 0;
  long ids_differ_off_edges = 0;  // of those, at an edge in neither image (image_compare.hpp)
  // Against a z-buffered reference: the part that comes from visibility by priority order.
  PriorityAttribution priority;
};
Comparison compare_run(int frame, int channel, const RasterImage& got, const RasterImage& reference);
// Fills c.priority from `priority_reference` (the same reference with visibility by priority).
void attribute_priority(Comparison& c, const RasterImage& got, const RasterImage& reference,
                        const RasterImage& priority_reference);
nlohmann::ordered_json comparison_json(const Comparison& c);
// An SSIM as the tables print it (4 decimals) and as the reports hold it; NaN (an image smaller
// than the window, image/ssim.hpp) is "-" and null.
std::string ssim_text(double ssim);
nlohmann::ordered_json ssim_json(double ssim);

// Totals over images: PSNR over all pixels, the mean SSIM (all.ssim()), the lowest image of each,
// maximum errors, counts.
struct ComparisonTotals {
  ImageError all;
  long images = 0, ids_differ = 0, ids_differ_off_edges = 0;
  PriorityAttribution priority;
  double min_psnr = 1e9;
  int worst_frame = 0, worst_channel = 0;
  double min_ssim = 2;  // of the images that have one (all.has_ssim())
  int worst_ssim_frame = 0, worst_ssim_channel = 0;
  void add(const Comparison& c);
  int max_abs() const { return std::max({all.max_abs[0], all.max_abs[1], all.max_abs[2]}); }
};

}  // namespace cig::cli
