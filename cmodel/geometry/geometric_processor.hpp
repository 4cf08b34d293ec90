// Geometric processor (SPEC B), double precision: per channel, eye transform, back-face culling,
// clipping against the near plane and the pyramid sides, perspective division to
// (Xs, Ys, Zs, Is), and projection of light points. Input: the scene manager's priority list;
// output: the ScreenFrame that every raster engine consumes.
#pragma once

#include <cstdint>

#include "frame/screen_frame.hpp"
#include "manager/scene_manager.hpp"

namespace cig {

struct GeometryStats {
  std::uint64_t polygons_in = 0;  // polygons of the visible subobjects
  std::uint64_t backfacing = 0;   // culled as back faces
  std::uint64_t outside = 0;      // wholly outside one clipping plane
  std::uint64_t clipped = 0;      // crossed a plane and were cut
  std::uint64_t degenerate = 0;   // projected to zero screen area
  std::uint64_t polygons_out = 0;
  std::uint64_t vertices_out = 0;
  std::uint64_t light_points_in = 0, light_points_out = 0;
  // Priority trees walked (scene/priority_compiler.hpp): nodes visited, each one plane test
  // (3 multiplies, 3 adds and a compare: seed 000's operation units, see bsp_operations()).
  std::uint64_t bsp_subobjects = 0, bsp_nodes = 0;
  double ms = 0;
};

// Arithmetic operations of the priority-tree walks (the manager's operation-count model): a node's
// side test n.eye - d is 3 multiplies and 3 adds/subtracts, then a compare.
constexpr std::uint64_t kBspNodeOperations = 7;

// The order in which stage B takes a compiled subobject's polygons: the tree walked with the eye's
// side of each node's plane, nearest subtree first (farthest first when back_to_front). Appends
// polygon indices to `order`; returns the nodes visited.
std::uint64_t walk_priority_tree(const std::vector<BspNode>& tree, const WorldSubobject& w, const glm::dvec3& eye,
                                 bool back_to_front, std::vector<std::uint32_t>& order);

ScreenFrame process_channel(const Scene& scene, const WorldDatabase& db, const ChannelView& view,
                            const PriorityList& list, GeometryStats& stats);

// Perspective division of an eye-space point inside the pyramid: Xs = x/(t z), Ys = -y/(t z)
// (Ys grows downward, in raster line order), clamped to [-1, 1] against rounding.
ScreenVertex project(const glm::dvec3& eye, double intensity, double tan_half_fov);

}  // namespace cig
