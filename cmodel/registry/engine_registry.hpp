// The registry of raster engines: the one place that knows every engine (--engine NAME). It sits
// above the engines (cmodel/reference, segment, quadtree, invparam), which know only the interface
// (engine/engine.hpp). Each engine declares beside its code what it models and draws, its settings
// (which its parser and `cig engines` share) and what it can drop (engine/engine_declaration.hpp);
// the registry lists the declarations and decides by their capabilities, never by an engine's name.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "engine/engine_declaration.hpp"

namespace cig {

struct EngineInfo {
  std::string name;
  std::string models;                     // the stage and the seed it models
  EngineCapabilities can;                 // what it draws and models, as its declaration says
  bool light_points;                      // draws light points (those that cannot say so in their drop kinds)
  std::vector<EngineOptionSpec> options;  // its --engine-opt keys, subpixel= included where it applies
  std::vector<DropKind> drops;            // the keys of its report's "dropped"
};

// Every engine, in the order --engine lists them.
const std::vector<EngineInfo>& engine_infos();
// InputError (naming --engine and the known engines) for an unknown name.
const EngineInfo& engine_info(const std::string& name);

// Throws InputError (naming the option) for an unknown engine or an option it does not accept.
std::unique_ptr<RasterEngine> make_engine(const std::string& name, const EngineOptions& options);
// The same checks without making the engine (a command checks its options before any work).
void check_engine_options(const std::string& name, const EngineOptions& options);
// The engine that declares itself the reference (the ground truth --reference names).
std::string reference_engine_name();
std::vector<std::string> engine_names();
// The engines that draw polygons (every one but stage F's, which draws a scene's convex polyhedra
// and refuses a frame of polygons only, such as a polygon list).
std::vector<std::string> polygon_engine_names();

}  // namespace cig
