// Float reference image generator: the ground truth every engine is measured against.
//
//  * coverage: 4 x 4 samples per pixel on the formatter grid (sample_lattice.hpp), exact
//    watertight edge tests with the top-left tie rule (coverage.hpp);
//  * visibility: z-buffer in double on w = 1/Zs, which is exactly affine in screen space for a
//    planar polygon (so depth is perspective-correct); equal depths go to the polygon earlier in
//    the priority list; the snapped variant keeps the exact depth planes;
//  * intensity: Gouraud as the seed defines it (eq. 3): along the left and right edges by Y, then
//    linearly along the row; colour = polygon colour x I;
//  * fog: linear in eye depth between fog start and end, towards the fog colour;
//  * light points: discs of diameter D = min(2048*Ds, 7) grid units (eq. 1), visible or hidden as
//    a whole: drawn when the light is at least as near as the polygon surface at its centre
//    (a point source; its exaggerated disc is not cut by the ground behind it);
//  * non-opaque polygons are screen-door transparent (half the samples of a fixed checkerboard);
//  * resolve: box filter over the 16 samples, rounded to 8 bits; the id of a pixel is the
//    polygon owning most of its samples (ties: the earlier polygon; background loses ties).
#pragma once

#include <cstdint>

#include "formatter/formatter_twin.hpp"
#include "frame/screen_frame.hpp"
#include "image/raster_image.hpp"

namespace cig {

struct ReferenceStats {
  std::uint64_t polygons = 0, polygons_empty = 0;
  std::uint64_t samples_covered = 0;  // covered samples (before the depth test)
  std::uint64_t samples_written = 0;  // samples that passed the depth test when drawn
  std::uint64_t light_points = 0, light_samples = 0;
  double raster_ms = 0, resolve_ms = 0;
};

// Visibility: kDepth is the ground truth (the z-buffer above). kPriority lets the first polygon in
// the list that covers a sample own it, as the raster engines do (they are fed in priority order
// and trust it): with the same coverage, the pixels where the two differ are exactly those where
// the priority order and the z-buffer disagree, which is how an engine's residual is classified.
// Light points follow the list too under kPriority: a sample keeps the light earliest in the list,
// which shows unless a polygon earlier than it (index < its priority) owns the sample (the
// engines' light point units). Fog uses the depth of the owning polygon either way.
enum class Visibility { kDepth, kPriority };

// samples_per_side: 4 (the engines' 4 x 4), or 1, 2, 8, 16 (sample_lattice.hpp). threads: workers
// taking the image's strips of rows in turn (the same bits for any number).
RasterImage render_reference(const ScreenFrame& frame, ReferenceStats& stats,
                             Visibility visibility = Visibility::kDepth, int samples_per_side = 4, int threads = 1);

// The snapped reference: coverage (and Gouraud) from the vertices snapped to the formatter grid,
// depth from the exact vertices of `exact` (the same polygons unsnapped). Snapping X and Y while
// keeping each vertex's Z would tilt the 1/Z plane of every polygon by a different amount, so
// near-coplanar surfaces (a marking 5 cm above a runway) would z-fight; the depth of a point of a
// polygon does not depend on where the formatter rounds its vertices. `grid_bits`: the formatter
// grid snapped to (formatter/formatter_twin.hpp; 12 = eq. 1).
RasterImage render_reference_snapped(const ScreenFrame& exact, ReferenceStats& stats,
                                     Visibility visibility = Visibility::kDepth, int samples_per_side = 4,
                                     int threads = 1, int grid_bits = kSeedGridBits);

}  // namespace cig
