// Geometric processor (SPEC B), double precision: per channel, eye transform, back-face culling,
// clipping against the near plane and the pyramid sides, perspective division to
// (Xs, Ys, Zs, Is), and projection of light points. Input: the scene manager's priority list;
// output: the ScreenFrame that every raster engine consumes.
#pragma once

#include <cstdint>

#include "common/operation_units.hpp"
#include "frame/screen_frame.hpp"
#include "manager/scene_manager.hpp"

namespace cig {

// The cost of walking priority trees in the units of seed 000's operation table
// (common/operation_units.hpp): L memory reads and writes, C comparisons with a conditional jump,
// A additions, M multiplications. Per node: its record read (first, count, front, back, next: 5 L)
// and its stack entry pushed and popped (2 L); a partition node's side test n.eye against the
// offset reads the plane (4 L) and is 3 M, 2 A and 1 C; a run's "no children" test is 1 C; every
// polygon put on the list is 1 L.
struct PriorityWalkCost {
  std::uint64_t nodes = 0, partitions = 0;
  OperationCounts ops;
  void add(const PriorityWalkCost& o) {
    nodes += o.nodes;
    partitions += o.partitions;
    ops += o.ops;
  }
};

struct GeometryStats {
  std::uint64_t polygons_in = 0;  // polygons of the visible subobjects
  std::uint64_t backfacing = 0;   // culled as back faces
  std::uint64_t outside = 0;      // wholly outside one clipping plane
  std::uint64_t clipped = 0;      // crossed a plane and were cut
  std::uint64_t degenerate = 0;   // projected to zero screen area
  std::uint64_t polygons_out = 0;
  std::uint64_t vertices_out = 0;
  std::uint64_t light_points_in = 0, light_points_out = 0;
  std::uint64_t light_points_outside_beam = 0;  // inside the pyramid, but the eye lies outside their beam
  // Priority trees walked (scene/priority_compiler.hpp): subobjects, nodes visited, and the walk's
  // operations in seed 000's units (walk_priority_tree counts them).
  std::uint64_t bsp_subobjects = 0;
  PriorityWalkCost bsp;
  double ms = 0;
};

// The order in which stage B takes a compiled subobject's polygons: the tree walked with the eye's
// side of each node's plane, nearest subtree first (farthest first when back_to_front). Appends
// polygon indices to `order`; returns what the walk cost.
PriorityWalkCost walk_priority_tree(const std::vector<BspNode>& tree, const WorldSubobject& w, const glm::dvec3& eye,
                                    bool back_to_front, std::vector<std::uint32_t>& order);

ScreenFrame process_channel(const Scene& scene, const WorldDatabase& db, const ChannelView& view,
                            const PriorityList& list, GeometryStats& stats);

// Perspective division of an eye-space point inside the pyramid: Xs = x/(t z), Ys = -y/(t z)
// (Ys grows downward, in raster line order), clamped to [-1, 1] against rounding.
ScreenVertex project(const glm::dvec3& eye, double intensity, double tan_half_fov);

}  // namespace cig
