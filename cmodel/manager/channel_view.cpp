#include "manager/channel_view.hpp"

#include <cmath>

#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

namespace cig {

ChannelView make_channel_view(const Scene& scene, int frame, int channel) {
  const Pose pose = observer_pose(scene, frame);
  const Channel& ch = scene.channels[std::size_t(channel)];
  // Observer body axes, then the channel's offsets in the observer's frame (yaw right, pitch up).
  glm::dmat3 body =
      body_to_world(pose.heading_deg, pose.pitch_deg, pose.roll_deg) * body_to_world(ch.yaw_deg, ch.pitch_deg, 0);
  // body_to_world columns are (right, forward, up); eye wants rows (right, up, forward).
  glm::dmat3 world_to_body = glm::transpose(body);
  glm::dmat3 swap(1, 0, 0, 0, 0, 1, 0, 1, 0);  // (x, y, z)_body -> (x, z, y)_eye
  ChannelView v;
  v.frame = frame;
  v.channel = channel;
  v.eye = pose.position;
  v.world_to_eye = swap * world_to_body;
  v.tan_half_fov = std::tan(glm::radians(0.5 * ch.fov_deg));
  v.near = scene.near;
  v.range = scene.range;
  return v;
}

ViewPyramid::ViewPyramid(double t, double near)
    : plane{{0, 0, 1, -near}, {1, 0, t, 0}, {-1, 0, t, 0}, {0, -1, t, 0}, {0, 1, t, 0}} {
  for (int k = 0; k < kClipPlanes; ++k)
    norm[k] = std::sqrt(plane[k].a * plane[k].a + plane[k].b * plane[k].b + plane[k].c * plane[k].c);
}

std::uint8_t ViewPyramid::outcode(const glm::dvec3& e) const {
  std::uint8_t c = 0;
  for (int k = 0; k < kClipPlanes; ++k)
    if (plane[k].distance(e) < 0) c |= std::uint8_t(1u << k);
  return c;
}

}  // namespace cig
