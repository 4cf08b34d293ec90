// Stage A's visibility unit on the data path (cmodel/manager/visibility_unit.hpp): the scene
// manager decides V[i] by the hls/manager kernel. Against its double twin on random worlds and on
// every airfield frame: the kernel keeps every object the twin keeps (it is conservative), and an
// object only the kernel keeps lies within the margin derived below of the true pyramid; spheres
// beyond the kernel's formats are kept and counted, not decided by clamped values.
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "generator/image_generator.hpp"
#include "manager/scene_manager.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

namespace cig {
namespace {

using manager_raw::kU;  // the world's LSB

// How far beyond the true pyramid a sphere the kernel keeps can lie, in metres (a radius the twin
// must then keep). hls/manager/visibility.hpp bounds it, on the kernel's quantized inputs, by
// M = eps + ceil_u(2^-16 R) + 2 u, eps = 4 u + ceil_u(2^-16 |d|_1), R = r_q + eps; so
// M <= 8 u + 2^-16 (|d|_1 + R) with R <= r + 6 u + 2^-16 |d|_1 (r_q <= r + u: rounded up).
// From the quantized inputs to the true ones: the eye-space centre moves by at most
// 3.47 u + 2^-16 |d|_1 (the header's point 2), the radius by u, t rounded up by < 2^-16 moves a
// side plane by < 2^-16 z <= 2^-16 |d|_1, near rounded down by < u. In all
// 14 u + 3 2^-16 |d|_1 (1 + 2^-16) + 2^-16 (r + 6 u) < 14 u + 2^-14 |d|_1 + 2^-16 (r + 6 u).
double kernel_margin(const ChannelView& v, const glm::dvec3& centre, double r) {
  const glm::dvec3 d = centre - v.eye;
  const double l1 = std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z);
  return 14 * kU + std::ldexp(l1, -14) + std::ldexp(r + 6 * kU, -16);
}

bool twin_keeps(const ChannelView& v, const glm::dvec3& centre, double r) {
  VisibilityUnitStats unused;
  return VisibilityUnit(v, VisibilityArith::kDouble).visible(centre, r, unused);
}

WorldDatabase random_world(std::mt19937_64& rng, int count, double extent) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  WorldDatabase db;
  for (int i = 0; i < count; ++i) {
    WorldObject o;
    o.centre = glm::dvec3(unit(rng) - 0.5, unit(rng) - 0.5, (unit(rng) - 0.5) * 0.05) * extent;
    o.radius = std::pow(10.0, unit(rng) * 5 - 2);  // 1 cm to 1 km
    db.objects.push_back(o);
  }
  return db;
}

ChannelView random_view(std::mt19937_64& rng, double extent) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  ChannelView v;
  v.eye = glm::dvec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) * 0.01) * extent;
  const double heading = unit(rng) * 6.2832, pitch = (unit(rng) - 0.5) * 1.2;
  const glm::dvec3 f(std::cos(pitch) * std::cos(heading), std::cos(pitch) * std::sin(heading), std::sin(pitch));
  const glm::dvec3 r = glm::normalize(glm::cross(f, glm::dvec3(0, 0, 1)));
  v.world_to_eye = glm::transpose(glm::dmat3(r, glm::cross(r, f), f));
  v.tan_half_fov = std::tan((5 + unit(rng) * 100) * 3.14159265358979 / 360);
  v.near = 0.1 + unit(rng) * 5;
  return v;
}

// Kernel against twin on one view: returns the objects only the kernel keeps.
long compare_units(const WorldDatabase& db, const ChannelView& v) {
  ManagerOptions kernel, twin;
  twin.visibility = VisibilityArith::kDouble;
  SceneManagerStats ks, ts;
  const std::vector<std::uint32_t> k = potentially_visible(db, v, kernel, ks);
  const std::vector<std::uint32_t> t = potentially_visible(db, v, twin, ts);
  EXPECT_TRUE(std::includes(k.begin(), k.end(), t.begin(), t.end())) << "the kernel culls a sphere the twin keeps";
  EXPECT_EQ(ks.unit.spheres, db.objects.size());
  EXPECT_EQ(ks.unit.spheres_out_of_format, 0u);
  std::vector<std::uint32_t> extra;
  std::set_difference(k.begin(), k.end(), t.begin(), t.end(), std::back_inserter(extra));
  for (std::uint32_t i : extra) {
    const WorldObject& o = db.objects[i];
    EXPECT_TRUE(twin_keeps(v, o.centre, o.radius + kernel_margin(v, o.centre, o.radius)))
        << "object " << i << " lies beyond the derived margin";
  }
  return long(extra.size());
}

TEST(VisibilityUnit, KernelKeepsWhatTheTwinKeepsWithinTheMarginOnRandomWorlds) {
  std::mt19937_64 rng(30);
  long extra = 0, views = 0;
  for (double extent : {200.0, 20000.0, 1.5e6}) {  // the last reaches the formats' +-2^20 m
    const WorldDatabase db = random_world(rng, 4000, extent);
    for (int n = 0; n < 25; ++n, ++views) extra += compare_units(db, random_view(rng, extent));
  }
  std::printf("visibility unit: %ld views x 4000 objects, %ld kept by the kernel only\n", views, extra);
}

TEST(VisibilityUnit, KernelKeepsWhatTheTwinKeepsOnEveryAirfieldFrame) {
  const Scene scene = load_scene(test::source_path("scenes/airfield.json"));
  const WorldDatabase db = build_world_database(scene);
  long extra = 0;
  for (int frame = 0; frame < scene.frame_count(); frame += 5)
    for (int c = 0; c < int(scene.channels.size()); ++c) extra += compare_units(db, make_channel_view(scene, frame, c));
  std::printf("visibility unit on the airfield: %ld objects kept by the kernel only\n", extra);
}

TEST(VisibilityUnit, SpheresBeyondTheFormatsAreKeptAndCounted) {
  WorldDatabase db;
  WorldObject near_eye, far_out;
  near_eye.centre = {0, 50, 0}, near_eye.radius = 1;  // in front of the eye
  far_out.centre = {0, 3e6, 0}, far_out.radius = 1;   // beyond +-2^20 m
  db.objects = {near_eye, far_out};
  ChannelView v;
  v.eye = {0, 0, 0};
  v.world_to_eye = glm::transpose(glm::dmat3({1, 0, 0}, {0, 0, 1}, {0, 1, 0}));  // looking along +y
  v.tan_half_fov = 0.5, v.near = 1;
  ManagerOptions kernel;
  SceneManagerStats st;
  EXPECT_EQ(potentially_visible(db, v, kernel, st), (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(st.unit.spheres, 2u);
  EXPECT_EQ(st.unit.spheres_out_of_format, 1u);
  // Behind the eye, beyond the formats: still kept (not decided on clamped values), and counted.
  db.objects[1].centre = {0, -3e6, 0};
  SceneManagerStats behind;
  EXPECT_EQ(potentially_visible(db, v, kernel, behind), (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(behind.unit.spheres_out_of_format, 1u);
  ManagerOptions twin;
  twin.visibility = VisibilityArith::kDouble;
  SceneManagerStats ts;
  EXPECT_EQ(potentially_visible(db, v, twin, ts), (std::vector<std::uint32_t>{0}));
}

}  // namespace
}  // namespace cig
