// One channel's view for one frame: the observer's pose combined with the channel's yaw/pitch
// offsets and field of view (SPEC A.1: the rotation matrix B).
#pragma once

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

  glm::dvec3 to_eye(const glm::dvec3& world) const { return world_to_eye * (world - eye); }
};

ChannelView make_channel_view(const Scene& scene, int frame, int channel);

}  // namespace cig
