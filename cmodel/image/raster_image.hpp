// What every raster engine produces for one image, and the resolve that every engine shares: the
// per-pixel polygon id from the owners of the pixel's samples. The engine interface
// (engine/engine.hpp) and the float reference both build on it; neither depends on the other.
#pragma once

#include <cstdint>

#include "image/image.hpp"

namespace cig {

// An engine's output image and its per-pixel polygon ids.
struct RasterImage {
  Image image;
  IdBuffer ids;
};

// The id of a pixel from its samples' owners (polygon index, -1 none): the polygon owning most
// samples; ties go to the earlier polygon, the background loses ties. Sorts `ids`.
std::int32_t majority_owner(std::int32_t* ids, int count);

}  // namespace cig
