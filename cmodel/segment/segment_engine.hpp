// The segment processor as a raster engine (SPEC C-D): "segment" runs the bit-accurate hls/
// kernels (formatter, edge generator, frame memory, overload protection, segment generator, light
// coding table, Y sorter, video channel) in a chosen format set; "segment-double" runs the same
// kernels on their double twins, so that the error of the algorithm (quadrilateral segments,
// priority instead of depth, per-line I, linear Z) separates from the error of quantization.
#pragma once

#include <memory>
#include <vector>

#include "engine/engine_declaration.hpp"

namespace cig {

// `segment` and (twin) `segment-double`: the rows the registry lists (engine/engine_declaration.hpp).
const EngineDeclaration& segment_engine_declaration(bool twin);

// Options (--engine-opt): segment_engine_options() (the twin has no format=).
std::unique_ptr<RasterEngine> make_segment_engine(const EngineOptions& options, bool twin);
std::vector<EngineOptionSpec> segment_engine_options(bool twin);
// What a full memory loses (the report's "dropped"): polygons_overload, polygons_frame_memory_full,
// segments_segment_memory_full (a light's segments included). Nothing else is left out: the
// overload threshold never drops a light point (its segments count with the protected polygons'
// before the threshold is chosen), a light's chords fit its kMaxLightSegments on every lattice the
// engine takes (at most 4096 samples a side: rows 1 grid unit apart, a disc of 7 units), and a
// polygon no sample row crosses after snapping covers no sample, so leaving it out loses nothing
// (the report's polygons_degenerate counts them).
const std::vector<DropKind>& segment_drop_kinds();

}  // namespace cig
