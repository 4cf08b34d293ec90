// `--engine quadtree` (and its double twin `quadtree-double`): the recursive-subdivision raster
// processor of seed 004 (SPEC E): formatter -> setup -> the PEs of the chosen architecture, run
// clock by clock by the architecture model (arch_model.hpp) -> pixel processor. Options
// (--engine-opt KEY=VALUE, or the CLI's --arch, --masks and --start-window): the table of
// quadtree_engine_options() (arch, masks, start, format, fifo, clock-ns, spp).
//
// It drops nothing: its memories (the pixel frame, the priority masks) are sized by the raster,
// every piece of every polygon is subdivided to the pixels it covers or to a mask that hides it,
// and every light point is drawn by the light point unit. The report's pixels_full and
// mask_words_full count pixels and mask words that filled up, which is how the masks hide what
// lies behind, not a loss; pieces_hidden_by_masks are hidden, not dropped.
#pragma once

#include <memory>
#include <vector>

#include "engine/engine_declaration.hpp"

namespace cig {

// The clock period in ns the architecture model assumes unless clock-ns=T says otherwise (100 MHz:
// the report's frame_ms; `cig cosim --trace` draws a cycle as one period of it).
constexpr double kQuadDefaultClockNs = 10;

// `quadtree` and (twin) `quadtree-double`: the rows the registry lists (engine/engine_declaration.hpp).
const EngineDeclaration& quadtree_engine_declaration(bool twin);

std::unique_ptr<RasterEngine> make_quadtree_engine(const EngineOptions& options, bool twin);
std::vector<EngineOptionSpec> quadtree_engine_options(bool twin);  // the twin has no format=

}  // namespace cig
