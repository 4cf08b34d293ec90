// Loads and validates a scene (format: scenes/README.md). Every rule broken throws InputError
// naming the file, the JSON path (or the OBJ file and line) and the rule.
#pragma once

#include <string>

#include "scene/scene.hpp"

namespace cig {

Scene load_scene(const std::string& file);
Scene parse_scene(const std::string& text, const std::string& file);

// Whole-pipeline rule on raster sizes: a power of two in [kMinRaster, kMaxRaster].
bool valid_raster_size(long long n);

}  // namespace cig
