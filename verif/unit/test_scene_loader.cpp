// The loaders accept every documented example and every scene shipped in scenes/, and read them
// as documented.
#include <filesystem>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "frame/screen_frame.hpp"
#include "scene/model_loader.hpp"
#include "scene/polygon_checks.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

namespace cig {
namespace {

TEST(SceneLoader, ReadmeExamplesParse) {
  const auto blocks = test::json_blocks(test::read_file(test::source_path("scenes/README.md")));
  ASSERT_EQ(blocks.size(), 3u);  // the third, a polyhedron example: test_polyhedra.cpp
  Scene s = parse_scene(blocks[0], "scenes/README.md#cig-scene");
  EXPECT_EQ(s.raster, 512);
  ASSERT_EQ(s.channels.size(), 3u);
  EXPECT_DOUBLE_EQ(s.channels[0].yaw_deg, -40);
  EXPECT_EQ(s.frame_count(), 11);
  ASSERT_EQ(s.objects.size(), 2u);
  const Object& hut = s.objects[1];
  EXPECT_TRUE(hut.sphere_given);
  EXPECT_DOUBLE_EQ(hut.sphere_radius, 10);
  ASSERT_EQ(hut.subobjects.size(), 2u);
  // Subobject defaults flow into polygons; polygon fields override them.
  EXPECT_TRUE(hut.subobjects[0].polygons[0].protect);
  EXPECT_DOUBLE_EQ(hut.subobjects[0].polygons[0].colour.r, 0.6);
  EXPECT_DOUBLE_EQ(hut.subobjects[0].polygons[4].colour.r, 0.5);
  EXPECT_TRUE(hut.subobjects[1].polygons[0].self_lit);
  EXPECT_EQ(hut.light_points.size(), 1u);
  // The ground has no sphere: it is computed and encloses the patch.
  EXPECT_FALSE(s.objects[0].sphere_given);
  EXPECT_NEAR(s.objects[0].sphere_radius, std::sqrt(2.0) * 500, 1e-6);
  // Background defaults to the fog colour but is given here.
  EXPECT_DOUBLE_EQ(s.background.r, 0.45);

  ScreenFrame f = parse_polygon_list(blocks[2], "scenes/README.md#cig-polys");
  EXPECT_EQ(f.raster, 64);
  ASSERT_EQ(f.polygons.size(), 2u);
  EXPECT_EQ(f.polygons[1].vertices.size(), 4u);
  EXPECT_EQ(f.light_points.size(), 1u);
}

TEST(SceneLoader, ShippedScenesLoad) {
  int count = 0;
  for (const char* dir : {"scenes", "scenes/small"}) {
    for (const auto& entry : std::filesystem::directory_iterator(test::source_path(dir))) {
      if (entry.path().extension() != ".json") continue;
      const std::string text = test::read_file(entry.path().string());
      SCOPED_TRACE(entry.path().string());
      if (text.find("\"cig-polys\"") != std::string::npos) {
        EXPECT_NO_THROW(parse_polygon_list(text, entry.path().string()));
      } else {
        Scene s = parse_scene(text, entry.path().string());
        EXPECT_GT(s.polygon_count() + s.light_point_count(), 0u);
      }
      ++count;
    }
  }
  EXPECT_GE(count, 3);
}

TEST(SceneLoader, AirfieldMeetsTheDefaultSceneBrief) {
  Scene s = load_scene(test::source_path("scenes/airfield.json"));
  EXPECT_EQ(s.raster, 512);
  EXPECT_EQ(s.channels.size(), 3u);
  EXPECT_GE(s.polygon_count(), 5000u);
  EXPECT_LE(s.polygon_count(), 50000u);
  EXPECT_GE(s.light_point_count(), 200u);
  EXPECT_GE(s.frame_count(), 100);
}

ModelMesh obj_text(const std::string& text, const std::string& name, const ModelOptions& o = {}) {
  return parse_model(text.data(), text.size(), "obj", name, o);
}

std::vector<glm::dvec3> corners(const ModelMesh& m, std::size_t face) {
  std::vector<glm::dvec3> v;
  for (auto i : m.faces[face].indices) v.push_back(m.vertices[i]);
  return v;
}

TEST(ModelLoader, ReadsObjIndexFormsAndNegativeIndices) {
  const std::string text =
      "# comment\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
      "f 1/1/1 2/1/1 3/1/1 4/1/1\nf -4//1 -2//1 -1//1\ng group\nusemtl x\n";
  const ModelMesh m = obj_text(text, "inline.obj");
  ASSERT_EQ(m.vertices.size(), 4u);  // welded by position: the two faces share their corners
  ASSERT_EQ(m.faces.size(), 2u);
  EXPECT_EQ(corners(m, 0), (std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
  EXPECT_EQ(corners(m, 1), (std::vector<glm::dvec3>{{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
  EXPECT_EQ(m.faces[1].indices, (std::vector<std::uint32_t>{0, 2, 3}));
  EXPECT_EQ(m.summary.triangulated_faces, 0u);  // a convex quad stays whole
}

TEST(ModelLoader, SkipsZeroAreaFacesAndTriangulatesDents) {
  const ModelMesh m = obj_text("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n", "z.obj");
  EXPECT_EQ(m.faces.size(), 1u);
  EXPECT_EQ(m.summary.degenerate_faces, 1u);
  const std::string dent = "v 0 0 0\nv 2 0 0\nv 2 2 0\nv 1 0.5 0\nf 1 2 3 4\n";
  const ModelMesh split = obj_text(dent, "dent.obj");
  EXPECT_EQ(split.summary.triangulated_faces, 1u);
  EXPECT_EQ(split.summary.triangles, 2u);
  ASSERT_EQ(split.faces.size(), 2u);
  for (std::size_t f = 0; f < 2; ++f) {
    EXPECT_EQ(split.faces[f].place.face, 0u);  // both triangles name the face they came from
    EXPECT_GT(newell_normal(corners(split, f)).z, 0) << "triangle " << f << " keeps the face's winding";
  }
  ModelOptions refuse;
  refuse.triangulate = false;
  try {
    obj_text(dent, "dent.obj", refuse);
    FAIL() << "a concave quad was accepted without triangulation";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "mesh 'defaultobject' face 0");
    EXPECT_NE(std::string(e.what()).find("not convex"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("\"triangulate\": false"), std::string::npos) << e.what();
  }
}

TEST(Observer, InterpolatesBetweenKeyframesAlongTheShorterArc) {
  Scene s;
  s.keyframes = {{0, {{0, 0, 0}, 350, 0, 0}}, {10, {{10, 20, 30}, 10, -4, 2}}};
  Pose p = observer_pose(s, 5);
  EXPECT_DOUBLE_EQ(p.position.x, 5);
  EXPECT_DOUBLE_EQ(p.position.z, 15);
  EXPECT_NEAR(std::remainder(p.heading_deg, 360.0), 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(p.pitch_deg, -2);
  EXPECT_DOUBLE_EQ(observer_pose(s, 10).roll_deg, 2);
}

}  // namespace
}  // namespace cig
