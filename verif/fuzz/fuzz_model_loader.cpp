// libFuzzer target: the model loader (cmodel/scene/model_loader: assimp's importers, the
// triangulation and the flattening into convex planar polygons) on arbitrary bytes. An input whose
// first byte is below the number of hints picks the format hint assimp is given and the rest is the
// file; any other input is the file itself, whose format assimp detects from its content (so the
// seeds are plain model files). Files the model names (an OBJ's .mtl) are not read. assimp runs in a
// child process, so a crash or hang inside it is a refused file here, not a finding.
#include <iterator>

#include "fuzz_input.hpp"
#include "scene/model_loader.hpp"

namespace {
const char* const kHints[] = {"obj", "ac", "3ds", "ply", "stl", "gltf", "glb", "dae", "fbx", "off", "x", "lwo"};
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const bool hinted = size > 0 && data[0] < std::size(kHints);
  const std::string hint = hinted ? kHints[data[0]] : "";
  const std::size_t skip = hinted ? 1 : 0;
  return cig::fuzz::run_input(data + skip, size - skip, [&](const std::string& bytes) {
    cig::ModelOptions options;
    options.seconds = 5;  // an importer that loops is refused after this (common/isolated_call)
    const cig::ModelMesh m = cig::parse_model(bytes.data(), bytes.size(), hint, "fuzz." + hint, options);
    // What the scene loader relies on: every polygon convex planar within the pipeline's limits,
    // every index a vertex.
    for (const cig::ModelFace& f : m.faces) {
      if (f.indices.size() < 3 || f.indices.size() > std::size_t(cig::kMaxSceneVertices))
        cig::fuzz::broken("a model polygon has fewer than 3 or more than kMaxSceneVertices corners");
      for (auto i : f.indices)
        if (i >= m.vertices.size()) cig::fuzz::broken("a model polygon indexes no vertex");
    }
  });
}
