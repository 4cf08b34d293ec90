// Wavefront OBJ reader for subobject geometry: vertices ("v") and faces ("f"), triangles and
// convex planar quads only. Errors name the file and line; the scene loader adds the scene place
// (objects[i].subobjects[j].obj) that referenced the model.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace cig {

struct ObjMesh {
  std::vector<glm::dvec3> vertices;
  std::vector<std::vector<std::uint32_t>> faces;  // zero-based, counter-clockwise from the front
  std::vector<std::size_t> face_lines;            // the line of each face's 'f' statement
  std::size_t degenerate_faces = 0;               // zero-area faces skipped
};

// Reads a regular file of at most `max_bytes` (a directory, device or FIFO is refused before any
// read), with or without a UTF-8 byte-order mark.
ObjMesh load_obj(const std::string& file, long long max_bytes = kDefaultMaxModelBytes);
ObjMesh parse_obj(const std::string& text, const std::string& file);

}  // namespace cig
