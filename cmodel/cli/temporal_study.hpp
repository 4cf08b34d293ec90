// Temporal image quality as simulator acceptance tests measure it (`cig temporal`; here beside the
// command because it drives the image generator and the engine registry), over a run of
// frames of one channel, per engine and samples per pixel:
//  * light-point scintillation: per isolated light, its rendered energy (a render of the frame's
//    light points alone, summed around the light) against its analytic energy (intensity x colour
//    x the disc's area, the formatter's diameter), and that ratio's change from frame to frame;
//  * edge crawl: the rendered position of an edge (a render of one object's surface alone, white on
//    black: a row's coverage across the edge is the edge's distance to the window's end) against
//    the edge's true projection, per screen row, and its change from frame to frame;
//  * popping: objects covering at least `pop_pixels` pixels in one frame and none in the next (or
//    the reverse), from the full render's ids, with the engine's drops beside them.
// Bounds from the sample lattice (S x S samples a pixel; docs/flightgear.md derives them): an
// edge's row estimate is off by less than 1/S pixel plus the grid snap of the fixed-point engines;
// a disc of diameter D pixels covers S^2 times its area to within 4 D S + 4 samples.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace cig {

struct TemporalOptions {
  int first = 0, last = 0, channel = 0;
  std::vector<std::string> engines{"float", "segment", "quadtree"};
  std::vector<int> spp{16};
  int pipelines = 1;
  std::string edge_object;  // object whose subobject "surface" (or only subobject) gives the edges; "": first runway_*
  double pop_pixels = 4;
};

// One (engine, spp) over the frames; *_frame: one value per frame (the first is 0) for the plot.
struct TemporalSeries {
  std::string engine;
  int spp = 16;
  // Scintillation: e = E / A - 1 per isolated light; de its change between consecutive frames.
  long light_frames = 0, light_deltas = 0, light_bound_violations = 0;
  double light_rms_error = 0, light_max_error = 0, light_rms_delta = 0, light_max_delta = 0;
  // Crawl (pixels): the row estimate's error and its change between frames at the same row.
  long edge_rows = 0, edge_deltas = 0, edge_bound_violations = 0;
  double edge_rms_error = 0, edge_max_error = 0, edge_rms_delta = 0, edge_max_delta = 0, edge_bound = 0;
  // Popping.
  long pops = 0, dropped = 0;  // dropped: the engine's drops summed over the frames
  std::vector<double> light_delta_frame, edge_delta_frame;
  std::vector<long> pops_frame;
  double ms = 0;
};

struct TemporalStudy {
  std::string edge_object;
  int raster = 0;
  std::vector<TemporalSeries> series;
};

TemporalStudy run_temporal_study(const Scene& scene, const TemporalOptions& options);

}  // namespace cig
