// Scene manager (SPEC A). This stage decides, per channel and frame, which objects and
// subobjects go to the geometric processor and in which priority order.
//
// Visibility flags from bounding spheres against the viewing pyramid (conservative: a sphere is
// culled only when it lies wholly outside one plane), for objects and then their subobjects. Then
// seed 000's preliminary sorting unit and subobject sorter (manager/occlusion_groups.hpp): visible
// objects whose spheres overlap form occlusion groups; groups are ordered by priority layer
// (higher first), then by the eye's power |c|^2 - R^2 (nearest first: a valid visibility order
// for non-overlapping spheres); an object alone keeps its modeller's subobject list (decals such as
// runway markings are listed before the surface they lie on), a group's objects' lists are merged
// by the distance to their subobjects' centres, each list keeping its own order. Front to back for
// the raster engines; back to front as a setting.
#pragma once

#include <cstdint>
#include <vector>

#include "manager/channel_view.hpp"
#include "manager/scene_quadtree.hpp"
#include "manager/visibility_unit.hpp"
#include "scene/world_database.hpp"

namespace cig {

struct ManagerOptions {
  const SceneQuadtree* tree = nullptr;  // the world's quadtree (culling.method other than brute force)
  CullSettings culling;
  bool back_to_front = false;    // the priority list farthest first (painter's order)
  bool pairwise_groups = false;  // the seed's O(N^2) pair loop instead of the sweep (same groups)
  VisibilityArith visibility = VisibilityArith::kKernel;  // V[i] by the hls/manager kernel or its twin
};

struct SceneManagerStats {
  std::uint64_t objects = 0, objects_visible = 0;
  std::uint64_t subobjects_tested = 0, subobjects_visible = 0;
  std::uint64_t groups = 0, grouped_objects = 0, largest_group = 0, pair_tests = 0;
  std::vector<std::uint64_t> group_sizes;  // [k]: groups of k objects (k >= 2; [0], [1] unused)
  CullStats cull;                          // the quadtree walk (seed 003)
  VisibilityUnitStats unit;                // the preliminary processing unit's spheres
  double sphere_ms = 0;                    // the kept objects' sphere tests
  double ms = 0;
};

// One visible object's run of subobjects, in priority order (highest first): list.subobjects
// [first, first + count). A group's merged list can visit an object more than once; its light
// points go with its first run only.
struct PriorityEntry {
  std::uint32_t object;
  std::uint32_t first = 0, count = 0;
  bool lights = true;
};

struct PriorityList {
  std::vector<PriorityEntry> objects;      // priority order, highest first
  std::vector<std::uint32_t> subobjects;   // the runs, one after another (no allocation per run)
  std::vector<std::uint32_t> group_first;  // the entry each occlusion group (or lone object) starts at
  bool back_to_front = false;              // farthest first: stage B walks priority trees the same way
  struct Run {
    const std::uint32_t *b, *e;
    const std::uint32_t* begin() const { return b; }
    const std::uint32_t* end() const { return e; }
  };
  Run run(const PriorityEntry& entry) const {
    const std::uint32_t* p = subobjects.data() + entry.first;
    return {p, p + entry.count};
  }
};

// Sphere against the viewing pyramid in eye coordinates: false only if wholly outside a plane.
bool sphere_may_be_visible(const ViewPyramid& pyramid, const glm::dvec3& centre_eye, double radius);

// The preliminary processing unit alone: the objects whose sphere may meet the viewing pyramid
// (through the quadtree when options.tree is set), in database order (the scene manager itself
// takes them in the tree's order; only exact ties of the eye power can order differently).
std::vector<std::uint32_t> potentially_visible(const WorldDatabase& db, const ChannelView& view,
                                               const ManagerOptions& options, SceneManagerStats& stats);

PriorityList manage_channel(const WorldDatabase& db, const ChannelView& view, SceneManagerStats& stats,
                            const ManagerOptions& options = {});

}  // namespace cig
