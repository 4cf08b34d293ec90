// `--engine float`: the float reference (reference_raster.hpp) behind the engine interface.
// Options: --snap (positions snapped to the formatter grid first, exact depth planes kept) and
// the --engine-opt table below (visibility, spp). It draws every polygon and light point it takes
// (its capacity, kMaxReferencePolygons, is checked before any work), so it drops nothing: the
// report's polygons_empty are polygons that cover no sample.
#pragma once

#include <memory>
#include <vector>

#include "engine/engine_declaration.hpp"

namespace cig {

// `float`: the row the registry lists (engine/engine_declaration.hpp).
const EngineDeclaration& reference_engine_declaration();
std::unique_ptr<RasterEngine> make_reference_engine(const EngineOptions& options);
// Its --engine-opt keys (engine_options.hpp): what make_reference_engine parses.
std::vector<EngineOptionSpec> reference_engine_options();

}  // namespace cig
