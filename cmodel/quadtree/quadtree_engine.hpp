// `--engine quadtree` (and its double twin `quadtree-double`): the recursive-subdivision raster
// processor of seed 004 (SPEC E): formatter -> setup -> the PEs of the chosen architecture, run
// clock by clock by the architecture model (arch_model.hpp) -> pixel processor. Options
// (--engine-opt KEY=VALUE, or the CLI's --arch, --masks and --start-window): the table of
// quadtree_engine_options() (arch, masks, start, format, fifo, clock, spp).
//
// It drops nothing: its memories (the pixel frame, the priority masks) are sized by the raster,
// every piece of every polygon is subdivided to the pixels it covers or to a mask that hides it,
// and every light point is drawn by the light point unit. The report's pixels_full and
// mask_words_full count pixels and mask words that filled up, which is how the masks hide what
// lies behind, not a loss; pieces_hidden_by_masks are hidden, not dropped.
#pragma once

#include <memory>
#include <vector>

#include "engine/engine.hpp"

namespace cig {

// The clock the architecture model assumes unless clock=MHZ says otherwise (the report's frame_ms;
// `cig cosim --trace` draws a cycle as one period of it).
constexpr double kQuadDefaultClockMhz = 100;

std::unique_ptr<RasterEngine> make_quadtree_engine(const EngineOptions& options, bool twin);
std::vector<EngineOptionSpec> quadtree_engine_options(bool twin);  // the twin has no format=

}  // namespace cig
