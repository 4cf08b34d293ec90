// One channel's view for one frame: the observer's pose combined with the channel's yaw/pitch
// offsets and field of view (SPEC A.1: the rotation matrix B).
#pragma once

#include <cstdint>
#include <limits>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace cig {

// Eye axes: x right, y up, z forward (depth). The viewing pyramid is |x| <= t*z, |y| <= t*z,
// z >= near, with t = tan(fov/2).
struct ChannelView {
  int frame = 0, channel = 0;
  glm::dvec3 eye{0};        // world position of the observer
  glm::dmat3 world_to_eye;  // rotation part; eye = world_to_eye * (p - eye)
  double tan_half_fov = 1;
  double near = 1;
  double range = std::numeric_limits<double>::infinity();  // objects wholly deeper are culled (Scene::range)

  glm::dvec3 to_eye(const glm::dvec3& world) const { return world_to_eye * (world - eye); }
};

ChannelView make_channel_view(const Scene& scene, int frame, int channel);

// Half-space a*x + b*y + c*z + d >= 0 in eye coordinates.
struct ClipPlane {
  double a, b, c, d;
  double distance(const glm::dvec3& e) const { return a * e.x + b * e.y + c * e.z + d; }
  ClipPlane complement() const { return {-a, -b, -c, -d}; }
};

// The five planes of the viewing pyramid, in clipping order: near, left, right, top, bottom.
// Bit k of an outcode refers to plane k. The scene manager culls bounding spheres against it
// (stage A), the geometric processor clips polygons against it (stage B).
struct ViewPyramid {
  ClipPlane plane[kClipPlanes];
  double norm[kClipPlanes];  // |(a, b, c)| of each plane, for sphere tests
  ViewPyramid(double tan_half_fov, double near);
  std::uint8_t outcode(const glm::dvec3& e) const;  // planes the point lies outside of
};

}  // namespace cig
