// The object-oriented quadtree and its culling methods (cmodel/manager/scene_quadtree.hpp): on
// random worlds of clustered objects (radii from 10 cm to 5 km, towns and scattered objects over
// 60 km) seen from random eyes, headings, pitches, fields of view and visibility ranges, and on every frame of the
// airfield, every method keeps exactly the objects the brute-force sphere test keeps (no false
// negative: the node tests are conservative; no false positive: the kept nodes' objects are
// tested one by one). The tree holds every object once, and every node's box holds its objects'
// spheres and its children's boxes.
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "manager/scene_manager.hpp"
#include "manager/scene_quadtree.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

namespace cig {
namespace {

WorldDatabase random_world(std::mt19937_64& rng, int count) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  WorldDatabase db;
  for (int i = 0; i < count; ++i) {
    WorldObject o;
    const bool town = unit(rng) < 0.6;
    const glm::dvec3 town_centre(std::floor(unit(rng) * 6) * 10000.0 - 30000.0, std::floor(unit(rng) * 6) * 10000.0, 0);
    o.centre = town ? town_centre + glm::dvec3(unit(rng) * 800, unit(rng) * 800, unit(rng) * 30)
                    : glm::dvec3(unit(rng) * 60000 - 30000, unit(rng) * 60000, unit(rng) * 300);
    o.radius = std::pow(10.0, unit(rng) * 4.7 - 1.0);
    db.objects.push_back(o);
  }
  return db;
}

ChannelView random_view(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  ChannelView v;
  v.eye = {unit(rng) * 70000 - 35000, unit(rng) * 70000 - 5000, unit(rng) * 3000 - 100};
  const double heading = unit(rng) * 6.2832, pitch = (unit(rng) - 0.5) * 1.2;
  const glm::dvec3 f(std::cos(pitch) * std::cos(heading), std::cos(pitch) * std::sin(heading), std::sin(pitch));
  const glm::dvec3 r = glm::normalize(glm::cross(f, glm::dvec3(0, 0, 1)));
  const glm::dvec3 u = glm::cross(r, f);
  v.world_to_eye = glm::transpose(glm::dmat3(r, u, f));  // rows: right, up, forward
  v.tan_half_fov = std::tan((5 + unit(rng) * 60) * 3.14159265358979 / 360);
  v.near = 0.5 + unit(rng) * 5;
  if (unit(rng) < 0.5) v.range = 1000 + unit(rng) * 20000;  // a visibility range, or none
  return v;
}

void expect_every_method_equals_brute_force(const WorldDatabase& db, const SceneQuadtree& tree, const ChannelView& view,
                                            const char* where, long& kept_less) {
  ManagerOptions brute;
  brute.visibility = VisibilityArith::kDouble;  // the exact test the node tests are conservative for
  SceneManagerStats st;
  const std::vector<std::uint32_t> want = potentially_visible(db, view, brute, st);
  for (CullMethod m : {CullMethod::kLineOfSight, CullMethod::kHierarchical, CullMethod::kProjection}) {
    ManagerOptions o;
    o.tree = &tree;
    o.culling.method = m;
    o.visibility = VisibilityArith::kDouble;
    SceneManagerStats s;
    ASSERT_EQ(potentially_visible(db, view, o, s), want) << where << " " << cull_method_name(m);
    EXPECT_LE(s.cull.nodes_kept, tree.node_count());
    kept_less += s.cull.objects_kept < db.objects.size() ? 1 : 0;
  }
}

TEST(SceneQuadtree, EveryMethodKeepsTheBruteForceObjectsOnRandomWorlds) {
  std::mt19937_64 rng(5);
  long kept_less = 0;
  for (int world = 0; world < 12; ++world) {
    const WorldDatabase db = random_world(rng, 200 + 700 * world);
    const SceneQuadtree tree(db);
    EXPECT_GT(tree.node_count(), 1u);
    for (int view = 0; view < 60; ++view)
      expect_every_method_equals_brute_force(db, tree, random_view(rng), "random world", kept_less);
  }
  EXPECT_GT(kept_less, 1000);  // the tree does skip objects
}

TEST(SceneQuadtree, EveryMethodKeepsTheBruteForceObjectsOnTheAirfield) {
  const Scene scene = load_scene(test::source_path("scenes/airfield.json"));
  const WorldDatabase db = build_world_database(scene);
  const SceneQuadtree tree(db);
  long kept_less = 0;
  for (int frame = 0; frame < scene.frame_count(); frame += 7)
    for (int c = 0; c < int(scene.channels.size()); ++c)
      expect_every_method_equals_brute_force(db, tree, make_channel_view(scene, frame, c), "airfield", kept_less);
}

// The line-of-sight method's three cone areas each decide some nodes: with D_near = D_far = 0
// every node takes the box test, with both huge the sphere test; all agree with brute force.
TEST(SceneQuadtree, ConeAreaThresholdsAtTheirExtremesStayExact) {
  std::mt19937_64 rng(9);
  const WorldDatabase db = random_world(rng, 3000);
  const SceneQuadtree tree(db);
  for (int view = 0; view < 40; ++view) {
    const ChannelView v = random_view(rng);
    SceneManagerStats st;
    ManagerOptions brute;
    brute.visibility = VisibilityArith::kDouble;  // the exact test (see above)
    const std::vector<std::uint32_t> want = potentially_visible(db, v, brute, st);
    for (const CullSettings& s :
         {CullSettings{CullMethod::kLineOfSight, 0, 0}, CullSettings{CullMethod::kLineOfSight, 1e9, 1e9},
          CullSettings{CullMethod::kLineOfSight, 500, 20000}}) {
      ManagerOptions o;
      o.tree = &tree;
      o.culling = s;
      o.visibility = VisibilityArith::kDouble;
      SceneManagerStats got;
      EXPECT_EQ(potentially_visible(db, v, o, got), want);
    }
  }
}

}  // namespace
}  // namespace cig
