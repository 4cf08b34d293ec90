// Loads and validates a scene (format: scenes/README.md). Every rule broken throws InputError
// naming the file, the JSON path (or the OBJ file and line) and the rule.
#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

#include "scene/priority_compiler.hpp"
#include "scene/scene.hpp"

namespace cig {

// Settings of the loader (cig's --max-model-mb, --max-model-seconds, --priority-cache and
// --modeller-order).
struct SceneLimits {
  long long max_model_bytes = kDefaultMaxModelBytes;   // largest model file read
  double max_model_seconds = kDefaultMaxModelSeconds;  // time assimp may take to read one model
  PriorityCompilerOptions priority;                    // the priority compiler, run after loading
};

Scene load_scene(const std::string& file, const SceneLimits& limits = {});
Scene parse_scene(const std::string& text, const std::string& file, const SceneLimits& limits = {});
// The scene of a parsed document (parse_json_text), for a caller that has parsed it already.
Scene scene_of_document(const nlohmann::json& doc, const std::string& file, const SceneLimits& limits = {});

// Whole-pipeline rule on raster sizes: a power of two in [kMinRaster, kMaxRaster].
bool valid_raster_size(long long n);

}  // namespace cig
