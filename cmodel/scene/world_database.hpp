// The scene placed in world coordinates, with everything that does not change from frame to
// frame computed once at load: world vertices, face planes, crease-aware Gouraud vertex
// intensities (SPEC B: a vertex normal averages the normals of the faces sharing the vertex),
// bounding spheres of objects and subobjects. Objects have static poses, so none of this is
// recomputed per frame or per channel.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace cig {

struct WorldSubobject {
  std::vector<glm::dvec3> vertices;         // world coordinates
  std::vector<glm::dvec3> face_normal;      // unit, world, one per polygon (front side)
  std::vector<double> face_offset;          // plane: dot(face_normal, p) = face_offset
  std::vector<std::uint32_t> first_corner;  // polygon i's corners: [first_corner[i], first_corner[i+1])
  std::vector<double> corner_intensity;     // Gouraud intensity per polygon corner, [0, 1]
  glm::dvec3 centre{0};                     // bounding sphere, world
  double radius = 0;
};

// What stage B needs of a directional light (LightPoint::beam, ::below), placed in the world once
// at load, so that a frame costs a few dot products per such light and angles only inside the
// lobe's bounds.
struct WorldLightDirection {
  std::uint32_t light = 0;  // its index in the object's light points
  bool beam = false, below = false;
  // The lobe: the axis' azimuth frame in world coordinates (right, along, up: the object's
  // horizontal placed by its pose), the axis' elevation and the half-widths (radians), and the
  // bounds of the rectangle of (azimuth, elevation) that holds the lobe, as sines and cosines:
  // |da| < h is cos(da) > cos h, and lo < el < hi is sin(el - lo) > 0 and sin(hi - el) > 0.
  glm::dvec3 right{1, 0, 0}, along{0, 1, 0}, up{0, 0, 1};
  double elevation = 0, horizontal = 1, vertical = 1;
  double cos_horizontal = 0, sin_lo = -1, cos_lo = 0, sin_hi = 1, cos_hi = 0;
  // The transition: the eye is below it when (eye - light).z < sin_below |eye - light| (world z).
  double sin_below = 0;
  Rgb below_colour{1, 0, 0};
};

struct WorldObject {
  std::vector<WorldSubobject> subobjects;
  std::vector<glm::dvec3> light_positions;            // world
  std::vector<WorldLightDirection> light_directions;  // the directional lights only, by index
  glm::dvec3 centre{0};
  double radius = 0;
  int layer = 0;
  bool subobjects_by_distance = false;
  // A convex polyhedron's face planes in world coordinates (Object::hull placed): outward unit
  // normal, hull_normal . p = hull_offset on the face; empty for other objects.
  std::vector<glm::dvec3> hull_normal;
  std::vector<double> hull_offset;
};

struct WorldDatabase {
  std::vector<WorldObject> objects;
  bool has_polyhedra = false;  // some object is a convex polyhedron (stage F's input)
};

WorldDatabase build_world_database(const Scene& scene);

// Intensity of a surface with unit normal n under the scene's sun and ambient light.
double gouraud_intensity(const Lighting& l, const glm::dvec3& n);

}  // namespace cig
