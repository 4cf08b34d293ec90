// Stress polygon lists (`cig stress`, issue 12): one class of numerically hard input each, from a
// seed, as cig-polys frames. The tests run every class through every engine
// (verif/stress/test_stress_classes.cpp); users write them to files to try a configuration.
//
// Classes (vertices on the formatter grid, so that snapping moves nothing, unless said):
//   slivers          full-width shallow triangles and quads, intensity ramps across the screen, fog
//   screen-edges     triangles and rectangles with vertices at X, Y = -1, 0 and 4095 grid units
//   depths           triangles at depths from 1e-30 to 1e38 m, and beyond the e8m7 range (1e-40,
//                    1e40); each spans a depth ratio of at most 4
//   intensities      planar intensity ramps, and quads whose four I are not planar (fan split)
//   decals           coplanar decals listed before the surfaces they lie on
//   fans             many triangles sharing one vertex (Gouraud fans), watertight
//   snap-nonconvex   thin convex polygons at fractional positions that the formatter's snap makes
//                    non-convex, bow-ties or reversed (off the grid by construction)
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "frame/screen_frame.hpp"

namespace cig::cli {

std::vector<std::string> stress_class_names();
// Whether a class keeps every vertex on the formatter grid.
bool stress_class_on_grid(const std::string& name);
// A list of class `name` from `seed` at `raster` lines (InputError for an unknown class).
ScreenFrame make_stress_list(const std::string& name, std::uint64_t seed, int raster = 256);

}  // namespace cig::cli
