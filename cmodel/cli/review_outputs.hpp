// What the commands write for a person to review a run (docs/review_outputs.md): the side-by-side
// image of `cig compare --out` (image/review_image.hpp).
#pragma once

#include <string>

#include "cli/frame_jobs.hpp"
#include "image/raster_image.hpp"

namespace cig::cli {

// DIR/frame_KKKK_chC_KIND.png: the file names of `cig compare --out` (KIND diff or side).
std::string compare_image_file(const std::string& dir, int frame, int channel, const std::string& kind);

// `cig compare --out DIR`: DIR/frame_KKKK_chC_side.png, engine | reference | error map, the
// comparison's numbers in its title strip.
void write_side_image(const std::string& dir, const Comparison& c, const std::string& engine,
                      const std::string& reference, const RasterImage& got, const RasterImage& want);

}  // namespace cig::cli
