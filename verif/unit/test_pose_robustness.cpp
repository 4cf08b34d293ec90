// Numerical robustness of stages A and B over the whole valid range (scenes/README.md, "Valid
// ranges"): random observer poses (deterministic seed) anywhere from next to the hut to 1e8 m away,
// looking straight up or down, rolled 180 degrees, with the near plane at both of its limits. For
// every pose and channel: every screen number is finite and inside the polygon-list ranges, the
// list `cig polys` would write reads back unchanged, and every engine draws it.
#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "frame/screen_frame.hpp"
#include "generator/image_generator.hpp"
#include "registry/engine_registry.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

namespace cig {
namespace {

Pose random_pose(std::mt19937_64& rng, int k) {
  std::uniform_real_distribution<double> u(-1, 1);
  Pose p;
  // Most poses near the hut (polygons cross the eye plane and the pyramid sides); some far away.
  const double reach = k % 10 == 0 ? kMaxWorldCoordinate : k % 3 == 0 ? 1e3 : 30;
  p.position = glm::dvec3(reach * u(rng), reach * u(rng), k % 10 == 0 ? reach * u(rng) : 1 + 10 * std::abs(u(rng)));
  // Mostly looking at the hut (heading clockwise from north, pitch up), give or take 20 degrees.
  const glm::dvec3 to_hut = -p.position;
  const double towards = std::atan2(to_hut.x, to_hut.y) * 180 / M_PI;
  const double up = std::atan2(to_hut.z, std::hypot(to_hut.x, to_hut.y)) * 180 / M_PI;
  p.heading_deg = k % 4 == 3 ? kMaxAngleDeg * u(rng) : std::remainder(towards + 20 * u(rng), 360.0);
  p.pitch_deg = k % 7 == 0 ? (k % 2 ? 90.0 : -90.0) : std::clamp(up + 20 * u(rng), -90.0, 90.0);
  p.roll_deg = k % 5 == 0 ? 180.0 : kMaxAngleDeg * u(rng);
  return p;
}

void expect_in_ranges(const ScreenFrame& f) {
  for (const ScreenPolygon& p : f.polygons)
    for (const ScreenVertex& v : p.vertices) {
      ASSERT_TRUE(std::abs(v.xs) <= 1 && std::abs(v.ys) <= 1) << v.xs << " " << v.ys;
      ASSERT_TRUE(v.zs >= kMinScreenDepth && v.zs <= kMaxScreenDepth) << v.zs;
      ASSERT_TRUE(v.is >= 0 && v.is <= 1) << v.is;
    }
  for (const ScreenLightPoint& l : f.light_points) {
    ASSERT_TRUE(std::abs(l.xs) <= 1 && std::abs(l.ys) <= 1 && l.zs >= kMinScreenDepth && l.zs <= kMaxScreenDepth);
    ASSERT_TRUE(l.ds >= 0 && l.ds <= 1) << l.ds;
  }
}

TEST(PoseRobustness, EveryPoseGivesAReadableListThatEveryEngineDraws) {
  Scene scene = load_scene(test::source_path("scenes/small/hut.json"));
  scene.raster = 32;
  scene.keyframes.resize(1);
  std::mt19937_64 rng(20261125);
  int polygons = 0, round_trips = 0;
  for (int k = 0; k < 120; ++k) {
    scene.keyframes[0].pose = random_pose(rng, k);
    scene.near = k % 4 == 0 ? kMinNear : k % 4 == 1 ? kMaxNear : 1.0;
    SCOPED_TRACE("pose " + std::to_string(k));
    const ImageGenerator pipeline(scene);
    for (int c = 0; c < int(scene.channels.size()); ++c) {
      nlohmann::ordered_json report;
      const ScreenFrame f = pipeline.geometry(0, c, report);
      expect_in_ranges(f);
      polygons += int(f.polygons.size());
      const std::string written = polygon_list_json(f);
      const ScreenFrame back = parse_polygon_list(written, "pose.polys.json");
      ASSERT_EQ(polygon_list_json(back), written);
      ++round_trips;
      for (const std::string& engine : polygon_engine_names()) {
        const EngineRun run = make_engine(engine, EngineOptions{})->render(back);
        ASSERT_EQ(run.out.image.width, 32) << engine;
        for (std::int32_t id : run.out.ids.id) ASSERT_TRUE(id >= -1 && id < int(back.polygons.size())) << engine;
      }
    }
  }
  EXPECT_EQ(round_trips, 240);
  EXPECT_GT(polygons, 200) << "the poses must put polygons on the screen";
}

}  // namespace
}  // namespace cig
