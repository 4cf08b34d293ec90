// Stage B's operation counts (GeometryStats::transform_ops, clip_ops and the plain counts) equal a
// hand count on tiny scenes, each item by the accounting of geometry/geometric_processor.hpp:
//  * a quad wholly inside the view: 4 vertices transformed, no intersection, 4 divisions;
//  * a quad crossing the right side of the pyramid: clipped against that plane only, 2 intersections;
//  * one light point inside the view.
#include <string>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "geometry/geometric_processor.hpp"
#include "manager/channel_view.hpp"
#include "manager/scene_manager.hpp"
#include "scene/scene_loader.hpp"
#include "scene/world_database.hpp"

namespace cig {
namespace {

using json = nlohmann::ordered_json;

// The eye at the origin looking north (eye x = world x, eye y = world z, depth = world y), 40
// degrees: the right side of the pyramid at depth 10 is x = 10 tan 20 = 3.64.
GeometryStats stage_b(const json& object) {
  const json scene_json = {{"format", "cig-scene"},
                           {"version", 1},
                           {"raster", 64},
                           {"channels", json::array({{{"name", "c"}, {"fov", 40}}})},
                           {"observer", {{"keyframes", json::array({{{"frame", 0}, {"position", {0, 0, 0}}}})}}},
                           {"objects", json::array({object})}};
  const Scene scene = parse_scene(scene_json.dump(), "counts.json");
  const WorldDatabase db = build_world_database(scene);
  const ChannelView view = make_channel_view(scene, 0, 0);
  SceneManagerStats ms;
  const PriorityList list = manage_channel(db, view, ms);
  GeometryStats stats;
  process_channel(scene, db, view, list, stats);
  return stats;
}

// A quad facing the eye at depth 10, x from x0 to x1, z from -1 to 1 (counter-clockwise seen from
// the eye).
json quad(double x0, double x1) {
  return {{"name", "quad"},
          {"subobjects", json::array({{{"name", "face"},
                                       {"colour", {0.5, 0.5, 0.5}},
                                       {"vertices", {{x0, 10, -1}, {x1, 10, -1}, {x1, 10, 1}, {x0, 10, 1}}},
                                       {"polygons", json::array({{{"indices", {0, 1, 2, 3}}}})}}})}};
}

OperationCounts ops(std::uint64_t C, std::uint64_t O, std::uint64_t L, std::uint64_t A, std::uint64_t M,
                    std::uint64_t D) {
  OperationCounts c;
  c.C = C;
  c.O = O;
  c.L = L;
  c.A = A;
  c.M = M;
  c.D = D;
  return c;
}

// Processor 1 for one quad: 4 vertices x (9 M + 9 A + 6 L), the back-face test 3 M + 2 A + 4 L + 1 C.
const OperationCounts kQuadTransform = ops(1, 0, 4 * 6 + 4, 4 * 9 + 2, 4 * 9 + 3, 0);
// Processor 2 for one quad, unclipped: outcodes 4 x (15 M + 15 A + 5 C + 4 L); the trivial tests
// 4 x (1 L + 2 O) + 2 C and the clip buffer 4 x 4 L; projection 4 x (2 M + 2 D + 4 C + 4 L); area
// 4 x (2 M + 2 A) + 1 C.
const OperationCounts kQuadClip =
    ops(4 * 5 + 2 + 4 * 4 + 1, 4 * 2, 4 * 4 + 4 * 1 + 4 * 4 + 4 * 4, 4 * 15 + 4 * 2, 4 * 15 + 4 * 2 + 4 * 2, 4 * 2);

TEST(GeometryCounts, QuadInsideTheView) {
  const GeometryStats s = stage_b(quad(-1, 1));
  ASSERT_EQ(s.polygons_out, 1u);
  EXPECT_EQ(s.clipped, 0u);
  EXPECT_EQ(s.vertices_transformed, 4u);
  EXPECT_EQ(s.clip_intersections, 0u);
  EXPECT_EQ(s.divisions, 4u);
  EXPECT_EQ(s.transform_ops, kQuadTransform) << to_string(s.transform_ops);
  EXPECT_EQ(s.clip_ops, kQuadClip) << to_string(s.clip_ops);
}

TEST(GeometryCounts, QuadCrossingTheRightSide) {
  // x = 10 is outside the right plane (x <= 3.64 z), x = 0 inside: the bottom and top edges cross it.
  const GeometryStats s = stage_b(quad(0, 10));
  ASSERT_EQ(s.polygons_out, 1u);
  EXPECT_EQ(s.clipped, 1u);
  EXPECT_EQ(s.vertices_transformed, 4u);
  EXPECT_EQ(s.clip_intersections, 2u);
  EXPECT_EQ(s.divisions, 4u);  // 2 kept + 2 new vertices
  EXPECT_EQ(s.vertices_out, 4u);
  EXPECT_EQ(s.transform_ops, kQuadTransform) << to_string(s.transform_ops);
  // The clip: 5 plane bits tested (5 C); against the right plane 4 edges x (6 M + 6 A + 2 C),
  // 2 kept vertices x 4 L, 2 intersections x (9 A + 4 M + 1 D + 4 L), 1 C (3 left?).
  OperationCounts clip = kQuadClip;
  clip += ops(5 + 4 * 2 + 1, 0, 2 * 4 + 2 * 4, 4 * 6 + 2 * 9, 4 * 6 + 2 * 4, 2);
  EXPECT_EQ(s.clip_ops, clip) << to_string(s.clip_ops);
}

TEST(GeometryCounts, LightPointInsideTheView) {
  const json light = {{"position", {0, 20, 0}}, {"diameter", 0.3}, {"colour", {1, 1, 1}}, {"intensity", 0.8}};
  const GeometryStats s = stage_b({{"name", "lamp"}, {"position", {0, 0, 0}}, {"light_points", {light}}});
  ASSERT_EQ(s.light_points_out, 1u);
  EXPECT_EQ(s.vertices_transformed, 0u);  // light points are light_points_in
  EXPECT_EQ(s.divisions, 1u);
  // Processor 1: B (p - eye), 9 M + 9 A + 6 L.
  EXPECT_EQ(s.transform_ops, ops(0, 0, 6, 9, 9, 0)) << to_string(s.transform_ops);
  // Processor 2: outcode 15 M + 15 A + 5 C + 3 L and 1 C (inside?); projection 2 M + 2 D + 4 C +
  // 4 L; Ds 1 M + 1 D + 2 C, I f 1 M, Ds written 1 L.
  EXPECT_EQ(s.clip_ops, ops(5 + 1 + 4 + 2, 0, 3 + 4 + 1, 15, 15 + 2 + 2, 2 + 1)) << to_string(s.clip_ops);
}

}  // namespace
}  // namespace cig
