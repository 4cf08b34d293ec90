// The segment processor as a raster engine (SPEC C-D): "segment" runs the bit-accurate hls/
// kernels (formatter, edge generator, frame memory, overload protection, segment generator, light
// coding table, Y sorter, video channel) in a chosen format set; "segment-double" runs the same
// kernels on their double twins, so that the error of the algorithm (quadrilateral segments,
// priority instead of depth, per-line I, linear Z) separates from the error of quantization.
#pragma once

#include <memory>

#include "engine/engine.hpp"

namespace cig {

// Options (--engine-opt): format=coarse|medium|fine (default fine; ignored by the twin).
std::unique_ptr<RasterEngine> make_segment_engine(const EngineOptions& options, bool twin);

}  // namespace cig
