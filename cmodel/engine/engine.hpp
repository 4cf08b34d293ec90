// Raster engines behind one interface, so that the CLI and the verification harness drive any of
// them the same way: "float" (the reference, cmodel/reference), "segment" and "segment-double"
// (formatter + segment processor, cmodel/segment), "quadtree" and "quadtree-double" (recursive
// subdivision, cmodel/quadtree). Each consumes a ScreenFrame and produces a RasterImage (image and
// per-pixel ids, image/raster_image.hpp) and a report.
#pragma once

#include <cstddef>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/engine_options.hpp"
#include "frame/screen_frame.hpp"
#include "image/raster_image.hpp"
#include "scene/scene.hpp"

namespace cig {

struct FanSplit;  // engine/fan_split.hpp

// The float reference's polygons (and light points) per channel: its ids are 32-bit and it keeps
// every polygon's setup in memory, so the bound only keeps a channel within a few GB. The
// hardware engines take 65,536 (their 16-bit polygon ids).
constexpr std::size_t kMaxReferencePolygons = std::size_t{1} << 24;

struct EngineOptions {
  bool snap = false;                          // snap positions to the formatter grid first (float engine)
  bool fan_split = true;                      // split polygons with non-planar attributes (engine/fan_split.hpp)
  std::map<std::string, std::string> params;  // engine-specific settings (--engine-opt KEY=VALUE)
  int threads = 1;  // workers for one image (strips of lines where the engine splits an image; same bits)
  // --engine-opt subpixel=B: the formatter grid at 1/2^B pixel (eq. 1 generalised to
  // g = log2(raster) + B bits, formatter/formatter_twin.hpp); -1: eq. 1 as the seed has it.
  int subpixel_bits = -1;
};

struct EngineRun {
  RasterImage out;
  nlohmann::ordered_json report;  // what the engine did and took, per stage
};

class RasterEngine {
 public:
  virtual ~RasterEngine() = default;
  virtual const char* name() const = 0;
  // What this engine can leave out of an image: the keys of its report's "dropped" (every one
  // present, zeros included), with what each means (engine_options.hpp).
  virtual const std::vector<DropKind>& drop_kinds() const;
  // Renders a frame: non-planar polygons split into fans first (unless the setting is off), ids
  // mapped back to the input's polygons; the report counts the split ("fan_split") and what the
  // engine dropped ("dropped").
  EngineRun render(const ScreenFrame& frame);
  // Checks the engine's options (the formatter grid setting, then the engine's own) against a
  // raster size before any work (InputError).
  void check_raster(int raster) const {
    check_formatter_grid(raster);
    check_engine_raster(raster);
  }
  // Checks a frame (as split) against the engine's capacities (the polygons and lights its id
  // fields hold) and raster before any work, so that a command fails before its first output
  // (InputError).
  void check_frame(const ScreenFrame& frame) const;
  // The same capacities against a frame's counts alone, as soon as they are known and before any
  // polygon is built (a polygon list refused at 1 M polygons without reading them; InputError with
  // check_frame's message). Splitting into fans only adds polygons: a count over the limit here is
  // over it after the split too.
  virtual void check_counts(int /*frame*/, int /*channel*/, std::size_t /*polygons*/,
                            std::size_t /*light_points*/) const {}
  // Checks a scene as a whole before any work (InputError): an engine that draws only some of a
  // scene's objects refuses a scene with none of them, rather than a frame in the middle of a run.
  virtual void check_scene(const Scene& /*scene*/) const {}
  void set_fan_split(bool on) { fan_split_ = on; }
  bool fan_split() const { return fan_split_; }
  // The frame the engine proper rasterises, render's first step: `frame` with its non-planar
  // polygons split into fans unless the setting is off (`split` gets the split and its counts),
  // then on the formatter grid setting's grid (`snapped` holds that copy). The result is `frame`,
  // split.frame or `snapped`. The co-simulation (`cig cosim`) runs the stream of this frame.
  const ScreenFrame& engine_frame(const ScreenFrame& frame, FanSplit& split, ScreenFrame& snapped) const;
  // The fixed engines format on the 12-bit grid of eq. 1; with a sub-pixel setting their input
  // is first snapped to the coarser grid it names (g = log2(raster) + B <= 12, else InputError).
  void set_formatter_grid(int subpixel_bits) { subpixel_bits_ = subpixel_bits; }

  // Seed 000's rendering channels: `parts` are N disjoint, contiguous slices of one channel's
  // priority list (part 0 first, each with its own polygon and light indices); each part is
  // rasterised by its own pipeline on its own worker thread and the video stage merges them sample
  // by sample by priority (a sample shows the first part that covers it). For the engines that
  // resolve visibility by priority the image and ids equal render() of the whole list (while no
  // part's memories overflow where the whole list's do not). Ids are those of the whole list.
  // Engines that do not merge parts (renders_parts() false) raise InputError.
  EngineRun render_parts(const std::vector<ScreenFrame>& parts);
  virtual bool renders_parts() const { return false; }
  void check_renders_parts() const;  // InputError unless renders_parts()

 protected:
  // The engine proper, on the frame as split.
  virtual EngineRun render_frame(const ScreenFrame& frame) = 0;
  virtual void check_split_frame(const ScreenFrame& frame) const { check_raster(frame.raster); }
  virtual void check_engine_raster(int /*raster*/) const {}
  // The parts as split, rasterised and merged; ids of the concatenated split parts.
  virtual EngineRun render_split_parts(const std::vector<const ScreenFrame*>& parts);

 private:
  // The report's "dropped" with every key of drop_kinds(), in their order (0 where the engine
  // reported none), then any other key the engine put there.
  void complete_dropped(nlohmann::ordered_json& report) const;
  // The frame as the formatter's grid setting leaves it (`frame` itself without a setting).
  const ScreenFrame& on_formatter_grid(const ScreenFrame& frame, ScreenFrame& snapped) const;
  void check_formatter_grid(int raster) const;  // InputError when the setting needs more than 12 bits
  bool fan_split_ = true;
  int subpixel_bits_ = -1;
};

}  // namespace cig
