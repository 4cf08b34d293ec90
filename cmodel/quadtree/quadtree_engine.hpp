// `--engine quadtree` (and its double twin `quadtree-double`): the recursive-subdivision raster
// processor of seed 004 (SPEC E): formatter -> setup -> the PEs of the chosen architecture, run
// clock by clock by the architecture model (arch_model.hpp) -> pixel processor. Options
// (--engine-opt KEY=VALUE, or the CLI's --arch and --masks):
//   arch=STR        architecture of eq. 1 (architecture.hpp), default "np" (one PE per level)
//   masks=on|off    multilevel priority masks, default on
//   start=screen|bbox  where a polygon piece's subdivision starts: the whole screen (default, the
//                   seed) or its start window, the smallest window holding its bounding box
//                   (ArchConfig::start_window; same image, fewer cycles)
//   format=coarse|medium|fine   parameter formats (hls/quadtree/records.hpp), default fine
//   fifo=K          FIFO depth between stages, 1..64, default 2
//   clock=MHZ       the clock the report converts cycles at, default 100 (kQuadDefaultClockMhz)
#pragma once

#include <memory>

#include "engine/engine.hpp"

namespace cig {

// The clock the architecture model assumes unless clock=MHZ says otherwise (the report's frame_ms;
// `cig cosim --trace` draws a cycle as one period of it).
constexpr double kQuadDefaultClockMhz = 100;

std::unique_ptr<RasterEngine> make_quadtree_engine(const EngineOptions& options, bool twin);

}  // namespace cig
