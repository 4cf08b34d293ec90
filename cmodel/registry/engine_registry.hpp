// The registry of raster engines: the one place that knows every engine (--engine NAME). It sits
// above the engines (cmodel/reference, segment, quadtree, invparam), which know only the interface
// (engine/engine.hpp).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "engine/engine.hpp"

namespace cig {

// Throws InputError (naming the option) for an unknown engine or an option it does not accept.
std::unique_ptr<RasterEngine> make_engine(const std::string& name, const EngineOptions& options);
std::vector<std::string> engine_names();
// The engines that draw polygons (every one but stage F's, which draws a scene's convex polyhedra
// and refuses a frame of polygons only, such as a polygon list).
std::vector<std::string> polygon_engine_names();

}  // namespace cig
