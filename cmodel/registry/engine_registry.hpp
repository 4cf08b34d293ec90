// The registry of raster engines: the one place that knows every engine (--engine NAME). It sits
// above the engines (cmodel/reference, segment, quadtree, invparam), which know only the interface
// (engine/engine.hpp). Each engine's row says what it models; its settings and what it can drop
// come from the engine's own tables (engine/engine_options.hpp), which its parser and `cig
// engines` share.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "engine/engine.hpp"

namespace cig {

struct EngineInfo {
  std::string name;
  std::string models;                     // the stage and the seed it models
  bool bit_accurate;                      // the hls/ kernels' words; false: a double model (a twin, the reference)
  bool polygons;                          // draws the frame's polygons (every engine but stage F's)
  bool polyhedra;                         // draws the frame's convex polyhedra (stage F)
  bool light_points;                      // draws light points (those that cannot say so in their drop kinds)
  bool pipelines;                         // merges rendering pipelines (--pipelines)
  bool snap;                              // takes --snap
  std::vector<EngineOptionSpec> options;  // its --engine-opt keys, subpixel= included where it applies
  std::vector<DropKind> drops;            // the keys of its report's "dropped"
};

// Every engine, in the order --engine lists them.
const std::vector<EngineInfo>& engine_infos();
// InputError (naming --engine and the known engines) for an unknown name.
const EngineInfo& engine_info(const std::string& name);

// Throws InputError (naming the option) for an unknown engine or an option it does not accept.
std::unique_ptr<RasterEngine> make_engine(const std::string& name, const EngineOptions& options);
std::vector<std::string> engine_names();
// The engines that draw polygons (every one but stage F's, which draws a scene's convex polyhedra
// and refuses a frame of polygons only, such as a polygon list).
std::vector<std::string> polygon_engine_names();

}  // namespace cig
