// Wavefront OBJ reader for subobject geometry: vertices ("v") and faces ("f"), triangles and
// convex planar quads only. Errors name the file and line.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace cig {

struct ObjMesh {
  std::vector<glm::dvec3> vertices;
  std::vector<std::vector<std::uint32_t>> faces;  // zero-based, counter-clockwise from the front
  std::size_t degenerate_faces = 0;  // zero-area faces skipped
};

ObjMesh load_obj(const std::string& file);
ObjMesh parse_obj(const std::string& text, const std::string& file);

}  // namespace cig
