// Subobject models through assimp (the Open Asset Import Library, Debian's libassimp-dev): OBJ,
// AC3D, 3DS, PLY, STL, glTF 2, Collada, FBX and every other format assimp reads, flattened into one
// vertex list and convex planar polygons, the node hierarchy's transforms applied. Errors name the
// model file and the mesh and face; the scene loader adds the scene place
// (objects[i].subobjects[j].model) that referenced the model. assimp stays inside this file's
// implementation: nothing else in the C model includes its headers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace cig {

struct ModelOptions {
  long long max_bytes = kDefaultMaxModelBytes;  // each file the model reads: itself, an OBJ's .mtl, a glTF's .bin
  // "up": "y": the model's +y axis becomes the scene's +z (and +z becomes -y), the rotation an
  // object's pitch of 90 degrees makes; false takes the coordinates as the file gives them (z up).
  bool y_up = false;
  // Faces the pipeline cannot take (more than kMaxSceneVertices corners, concave, non-planar, not
  // simple) are triangulated by assimp's post-processing; false refuses them.
  bool triangulate = true;
  // assimp reads the model in a child process stopped after this many seconds (an importer that
  // loops on a hostile file); a crash or an exhausted memory limit there refuses the file too.
  double seconds = kDefaultMaxModelSeconds;
};

struct ModelFace {
  std::vector<std::uint32_t> indices;  // into ModelMesh::vertices, counter-clockwise from the front
  bool has_colour = false;             // the mesh's material gives a diffuse colour
  Rgb colour{1, 1, 1};
  ModelFaceRef place;  // the mesh and its face in the file, for messages
};

struct ModelMesh {
  std::vector<glm::dvec3> vertices;  // welded by exact position, in the order the faces use them
  std::vector<ModelFace> faces;
  std::vector<std::string> mesh_names;  // per assimp mesh: its name, or "" when the file gives none
  ModelSummary summary;
};

// Reads a regular file of at most `options.max_bytes` (a directory, device or FIFO is refused before
// any read, and so is every further file the model names) in whichever format assimp recognises.
ModelMesh load_model(const std::string& file, const ModelOptions& options = {});
// The same from memory; `format_hint` is the file extension assimp would see ("obj", "ply", ...).
// Files the model names (an OBJ's .mtl) are not read. For the libFuzzer target.
ModelMesh parse_model(const void* data, std::size_t size, const std::string& format_hint, const std::string& file,
                      const ModelOptions& options = {});

}  // namespace cig
