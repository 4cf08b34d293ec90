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

// Stage B on seed 001's two "Электроника МТ-70М" processors in a pipeline, counted in seed 000's
// units as the code runs (cmodel/timing/geometry_timing.hpp times them). The first does the matrix
// work, the second clipping and the perspective division (with the added divider):
//   transform_ops (processor 1)
//     per vertex and per light point   eye = B (p - eye): 3 A, then 9 M + 6 A (dmat3 * dvec3);
//                                      3 L read, 3 L written to the real-number channel
//     per polygon, back-face test      n . eye > D: 4 L (plane), 3 M + 2 A, 1 C. On processor 1:
//                                      a matrix-row-like product on world data, and a back face
//                                      culled there never crosses the channel
//     per polyhedron face (stage F)    R n: 9 M + 6 A; D - n . eye: 3 M + 3 A; 4 L read, 4 L written
//   clip_ops (processor 2)
//     per vertex and per light point   outcode, 5 planes x (3 M + 3 A + 1 C), the general
//                                      a x + b y + c z + d the code evaluates; 3 L (eye) read,
//                                      1 L (outcode) written; a light point: no outcode kept, 1 C
//                                      (inside?)
//     per front-facing polygon         per vertex 1 L (outcode) + 2 O (AND, OR); 1 C (all outside?);
//                                      then 4 L per vertex (eye, intensity) and 1 C (any outside?)
//     per polygon clipped              1 C per plane (its bit), and per plane clipped against as
//                                      clip.cpp counts: per edge 6 M + 6 A + 2 C, per intersection
//                                      9 A + 4 M + 1 D + 4 L, per kept vertex 4 L
//     per projected vertex             x/(t z), -y/(t z): 2 M + 2 D (the code forms t z twice),
//                                      2 clamps 4 C, 4 L written (Xs, Ys, Zs, Is); 1 division
//     per projected polygon            area: 2 M + 2 A per vertex, 1 C
//     per light point projected        as a vertex, plus Ds = D/(t z): 1 M + 1 D + 2 C (min, max),
//                                      I f: 1 M, 5 L written instead of 4; 1 division
//     per directional light            see directional_light (geometric_processor.cpp); sqrt and
//                                      atan2 count as 1 D each (the divider's iteration: an assumption,
//                                      seed 000's units have no function kind)
// Not counted here: the priority-tree walk (bsp below, its own record).
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
  OperationCounts transform_ops, clip_ops;  // processors 1 and 2 (above)
  std::uint64_t vertices_transformed = 0;   // subobject vertices to eye space (light points: light_points_in)
  std::uint64_t clip_intersections = 0;     // vertices made on crossing edges
  std::uint64_t divisions = 0;              // points through the perspective division (vertices, light centres)
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
