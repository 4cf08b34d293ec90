// What the loaders accept at the edges of their valid ranges (scenes/README.md, "Valid ranges"),
// and what they refuse before reading: the cases the bad-input corpus cannot hold as files.
#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "common/json_reader.hpp"
#include "frame/input_kind.hpp"
#include "frame/screen_frame.hpp"
#include "registry/engine_registry.hpp"
#include "scene/model_loader.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

namespace cig {
namespace {

std::string scene_with_sun(const std::string& direction) {
  return R"({"format": "cig-scene", "version": 1, "channels": [{"fov": 40}],
    "lighting": {"sun_direction": )" +
         direction + R"(},
    "observer": {"keyframes": [{"frame": 0, "position": [0, -10, 2]}]},
    "objects": [{"light_points": [{"position": [0, 0, 1], "diameter": 1}]}]})";
}

TEST(InputLimits, SunDirectionsOfAnyMagnitudeNormalise) {
  const Scene huge = parse_scene(scene_with_sun("[1e200, -1e200, 0]"), "huge.json");
  EXPECT_NEAR(huge.lighting.sun_direction.x, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(huge.lighting.sun_direction.y, -std::sqrt(0.5), 1e-15);
  const Scene tiny = parse_scene(scene_with_sun("[1e-200, 0, 0]"), "tiny.json");
  EXPECT_EQ(tiny.lighting.sun_direction.x, 1.0);
  const Scene denormal = parse_scene(scene_with_sun("[0, 0, 5e-324]"), "denormal.json");
  EXPECT_EQ(denormal.lighting.sun_direction.z, 1.0);
  EXPECT_THROW(parse_scene(scene_with_sun("[0, 0, 0]"), "zero.json"), InputError);
}

ModelMesh obj_text(const std::string& text, const std::string& name) {
  return parse_model(text.data(), text.size(), "obj", name);
}

TEST(InputLimits, ObjByteOrderMarkIsNotPartOfTheFirstVertex) {
  const std::string body = "v -1 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 3\n";
  const ModelMesh plain = obj_text(body, "plain.obj");
  const ModelMesh marked = obj_text("\xEF\xBB\xBF" + body, "marked.obj");
  ASSERT_EQ(marked.vertices.size(), 3u);
  EXPECT_EQ(marked.vertices, plain.vertices);
  EXPECT_EQ(marked.faces[0].indices, plain.faces[0].indices);
  const ModelMesh shipped = load_model(test::source_path("verif/bad_input/models/box_bom.obj"));
  EXPECT_EQ(shipped.vertices[0], glm::dvec3(-1, 0, 0));
}

// assimp keeps coordinates in single precision (ai_real is float in Debian's build): a denormal
// double is 0 there, and a coordinate beyond the float range is refused as not finite.
TEST(InputLimits, ModelCoordinatesAreFiniteFloats) {
  const ModelMesh m = obj_text("v 4.9e-324 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 3\n", "denormal.obj");
  EXPECT_EQ(m.vertices[0].x, 0.0);
  try {
    obj_text("v 1e999 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 3\n", "inf.obj");
    ADD_FAILURE() << "an infinite coordinate was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("inf.obj: mesh"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("vertex 0: coordinate is not a finite number"), std::string::npos) << e.what();
  }
}

// A FIFO would block a reader forever: it is refused from its file type, before any open().
TEST(InputLimits, FifoAndDevicesAreRefusedWithoutReading) {
  const std::string fifo =
      (std::filesystem::temp_directory_path() / ("cig_fifo_" + std::to_string(::getpid()))).string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  try {
    load_model(fifo);
    ADD_FAILURE() << "a FIFO was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is not a regular file"), std::string::npos) << e.what();
  }
  std::filesystem::remove(fifo);
  EXPECT_THROW(load_model("/dev/urandom"), InputError);
  EXPECT_THROW(load_polygon_list("/dev/zero"), InputError);
}

TEST(InputLimits, ModelSizeLimitIsASetting) {
  const std::string box = test::source_path("verif/bad_input/models/box_bom.obj");
  EXPECT_NO_THROW(load_model(box));
  try {
    ModelOptions small;
    small.max_bytes = 16;
    load_model(box, small);
    ADD_FAILURE() << "a model above the limit was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("more than the limit of 16 bytes (--max-model-mb)"), std::string::npos)
        << e.what();
  }
}

// Screen polygons may repeat a vertex (clipping through a corner): the list the geometric
// processor writes is read back.
TEST(InputLimits, PolygonListAcceptsRepeatedVertices) {
  const std::string text = R"({"format": "cig-polys", "version": 1, "raster": 64, "polygons": [
    {"vertices": [[-0.5, -0.5, 10, 1], [0.5, -0.5, 10, 1], [0.5, -0.5, 10, 1], [0, 0.5, 10, 1]]}]})";
  const ScreenFrame f = parse_polygon_list(text, "repeat.polys.json");
  EXPECT_EQ(f.polygons[0].vertices.size(), 4u);
  EXPECT_EQ(polygon_list_json(parse_polygon_list(polygon_list_json(f), "again")), polygon_list_json(f));
}

// Found by fuzz_polygon_list (30-minute campaign): a light at Xs = -0.0 was written "-0", which a
// JSON reader takes for the integer 0, so the written list read back with +0. Negative zero is
// written "-0.0" and keeps its sign.
TEST(InputLimits, NegativeZeroRoundTrips) {
  const std::string text = R"({"format": "cig-polys", "version": 1, "raster": 64, "polygons": [],
    "light_points": [{"centre": [-0.0, 0.1, 100], "diameter": 0.05}]})";
  const ScreenFrame f = parse_polygon_list(text, "minus_zero.polys.json");
  ASSERT_TRUE(std::signbit(f.light_points[0].xs));
  const std::string written = polygon_list_json(f);
  const ScreenFrame back = parse_polygon_list(written, "written");
  EXPECT_TRUE(std::signbit(back.light_points[0].xs));
  EXPECT_EQ(polygon_list_json(back), written);
}

// compare, sweep and cosim take a scene or a polygon list: the format field decides, so a scene
// with a channel called "cig-polys" is a scene.
TEST(InputLimits, InputKindComesFromTheFormatField) {
  const std::string scene = R"({"format": "cig-scene", "version": 1, "channels": [{"name": "cig-polys", "fov": 40}],
    "observer": {"keyframes": [{"frame": 0, "position": [0, -10, 2]}]},
    "objects": [{"light_points": [{"position": [0, 0, 1], "diameter": 1}]}]})";
  EXPECT_EQ(input_kind(scene, "scene.json"), InputKind::kScene);
  EXPECT_NO_THROW(parse_scene(scene, "scene.json"));
  EXPECT_EQ(input_kind(R"({"format": "cig-polys", "name": "cig-scene"})", "p.json"), InputKind::kPolygonList);
  EXPECT_THROW(input_kind(R"({"format": "cig-image"})", "x.json"), InputError);
  EXPECT_THROW(input_kind(R"(["cig-polys"])", "x.json"), InputError);
}

}  // namespace
}  // namespace cig

namespace cig {
namespace {

// The float reference takes a million polygons in one channel (issue 14): 1,048,576 triangles on
// a 256 x 256 raster, one per sample cell (4 x 4 per pixel), each covering its own cell's sample
// (legs of 1.5 cells: the sample at (0.5, 0.5) lies inside, its neighbours' at (1.5, 0.5) outside);
// every pixel's id is one of its own sixteen triangles.
TEST(InputLimits, FloatEngineTakesAMillionPolygons) {
  ScreenFrame f;
  f.raster = 256;
  const int per_side = 1024;  // 1024 x 1024 triangles, 4 x 4 per pixel
  f.polygons.reserve(std::size_t(per_side) * per_side);
  for (int j = 0; j < per_side; ++j)
    for (int i = 0; i < per_side; ++i) {
      ScreenPolygon p;
      const double x = -1 + 2.0 * i / per_side, y = -1 + 2.0 * j / per_side, d = 1.5 * 2.0 / per_side;
      p.vertices = {{x, y, 10, 1}, {x + d, y, 10, 1}, {x, y + d, 10, 1}};
      f.polygons.push_back(std::move(p));
    }
  ASSERT_EQ(f.polygons.size(), std::size_t(1) << 20);
  const auto engine = make_engine("float", {});
  engine->check_frame(f);
  const EngineRun run = engine->render(f);
  EXPECT_EQ(run.report["polygons"].get<std::size_t>(), f.polygons.size());
  for (int py = 0; py < 256; py += 51)
    for (int px = 0; px < 256; px += 37) {
      const std::int32_t id = run.out.ids.id[std::size_t(py) * 256 + std::size_t(px)];
      EXPECT_GE(id / per_side, 4 * py) << px << "," << py;
      EXPECT_LT(id / per_side, 4 * py + 4) << px << "," << py;
      EXPECT_GE(id % per_side, 4 * px) << px << "," << py;
      EXPECT_LT(id % per_side, 4 * px + 4) << px << "," << py;
    }
}

}  // namespace
}  // namespace cig
