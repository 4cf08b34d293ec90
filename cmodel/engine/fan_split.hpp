// Polygons whose vertex attributes are not planar (SPEC B's Gouraud I, or 1/Z of a polygon list
// that does not come from a planar face) have no single right interior: the seed's eq. 3 depends
// on the polygon's orientation on the screen, one plane per polygon on the fit. The rule every
// path shares (the float reference and every engine, for scenes and for `cig raster` lists): such
// a polygon is split into the triangle fan (0, k, k + 1) before rasterisation, in list order, so
// each piece has planar attributes and every engine interpolates the same function. A setting
// (EngineOptions::fan_split, `--fan-split off`), on by default, counted in each engine's report.
#pragma once

#include <cstdint>
#include <vector>

#include "frame/screen_frame.hpp"
#include "image/image.hpp"

namespace cig {

// Planarity tolerances. I: half an LSB of the formatter's I (eq. 1, 256 Is), below which the
// formatted vertices cannot tell the difference. 1/Z: 2^-12 of the polygon's largest 1/Z, a
// sixteenth of the e8m7 step (7 mantissa bits) the fog table resolves.
constexpr double kPlanarIntensityTolerance = 1.0 / 512;
constexpr double kPlanarInverseDepthTolerance = 1.0 / 4096;

// True when I and 1/Z of every vertex lie within the tolerances of the plane through the fan
// triangle of largest area (screen coordinates). Triangles are always planar.
bool attributes_planar(const ScreenPolygon& p);

struct FanSplit {
  ScreenFrame frame;                 // the frame the engines rasterise (empty when nothing is split)
  std::vector<std::int32_t> source;  // source[k]: the input polygon of split polygon k
  long polygons_split = 0;           // input polygons split into fans
  long triangles_added = 0;          // polygons the split added (each split n-gon adds n - 3)
};

// The frame with every non-planar polygon replaced by its fan; light points rank before the first
// piece of the polygon they ranked before. When every polygon is planar nothing is copied
// (polygons_split = 0, frame empty): the engines take the input as it is.
FanSplit split_nonplanar_polygons(const ScreenFrame& frame);

// Per-pixel ids of the split frame -> ids of the input frame.
void map_ids_to_source(IdBuffer& ids, const std::vector<std::int32_t>& source);

}  // namespace cig
