// `--engine float`: the float reference (reference_raster.hpp) behind the engine interface.
// Options: --snap (positions snapped to the formatter grid first, exact depth planes kept);
// --engine-opt visibility=depth (default, the z-buffer) | priority (list order, as the engines).
#pragma once

#include <memory>

#include "engine/engine.hpp"

namespace cig {

std::unique_ptr<RasterEngine> make_reference_engine(const EngineOptions& options);

}  // namespace cig
