// Scene manager (SPEC A). This stage decides, per channel and frame, which objects and
// subobjects go to the geometric processor and in which priority order.
//
// Implemented now: visibility flags from bounding spheres against the viewing pyramid
// (conservative: a sphere is culled only when it lies wholly outside one plane), for objects and
// then their subobjects; objects by priority layer (higher first), then by distance from the
// observer, nearest first (highest priority); subobjects in database order, which is the modeller's priority order (decals such as
// runway markings are listed before the surface they lie on).
// Planned (scene-manager issue): occlusion groups, depth-sorted group lists with the seed's
// two-list merge, channel loading from Nc disjoint lists, the seed's operation counts, and the
// object-oriented quadtree culling of seed 003.
#pragma once

#include <cstdint>
#include <vector>

#include "manager/channel_view.hpp"
#include "scene/world_database.hpp"

namespace cig {

struct SceneManagerStats {
  std::uint64_t objects = 0, objects_visible = 0;
  std::uint64_t subobjects_tested = 0, subobjects_visible = 0;
  double ms = 0;
};

// One visible object and its visible subobjects, in priority order (highest first).
struct PriorityEntry {
  std::uint32_t object;
  std::vector<std::uint32_t> subobjects;
};

struct PriorityList {
  std::vector<PriorityEntry> objects;  // priority order, highest first
};

// Sphere against the viewing pyramid in eye coordinates: false only if wholly outside a plane.
bool sphere_may_be_visible(const ViewPyramid& pyramid, const glm::dvec3& centre_eye, double radius);

PriorityList manage_channel(const WorldDatabase& db, const ChannelView& view, SceneManagerStats& stats);

}  // namespace cig
