// Models of many formats through assimp (cmodel/scene/model_loader): Debian's assimp-testmodels,
// with every expected count and extent derived from the file itself (its header, its statements,
// its accessors), not from what the loader printed once. Skipped when the package is missing.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "scene/model_loader.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

namespace cig {
namespace {

const std::string kModels = "/usr/share/assimp/models/";

#define REQUIRE_TESTMODELS()                                \
  if (!std::filesystem::exists(kModels + "OBJ/spider.obj")) \
  GTEST_SKIP() << "assimp-testmodels is not installed (tools/deps.sh installs it)"

std::string text_of(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Lines that start with `word` followed by a blank.
std::size_t count_statements(const std::string& file, const std::string& word) {
  std::istringstream in(text_of(file));
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);) n += line.rfind(word + " ", 0) == 0;
  return n;
}

// The number after `keyword` on a header line ("element face 6").
std::size_t header_count(const std::string& file, const std::string& keyword) {
  std::istringstream in(text_of(file));
  for (std::string line; std::getline(in, line);)
    if (line.rfind(keyword, 0) == 0) return std::stoul(line.substr(keyword.size()));
  return 0;
}

struct Box {
  glm::dvec3 lo{1e300}, hi{-1e300};
};

Box bounds(const ModelMesh& m) {
  Box b;
  for (const auto& v : m.vertices) {
    b.lo = glm::min(b.lo, v);
    b.hi = glm::max(b.hi, v);
  }
  return b;
}

// Every face of a file, drawn or skipped at zero area, is accounted for.
void expect_faces(const ModelMesh& m, std::size_t file_faces) {
  EXPECT_EQ(m.summary.faces, file_faces);
  EXPECT_EQ(m.faces.size() + m.summary.degenerate_faces - m.summary.triangles + m.summary.triangulated_faces,
            file_faces);
}

TEST(ModelLoader, ObjCountsItsFaceStatements) {
  REQUIRE_TESTMODELS();
  const std::string file = kModels + "OBJ/spider.obj";
  const ModelMesh m = load_model(file);
  expect_faces(m, count_statements(file, "f"));  // 1368, 56 of them of zero area
  EXPECT_EQ(m.summary.degenerate_faces, 56u);
  EXPECT_TRUE(m.faces[0].has_colour);  // spider.mtl gives each material a Kd
}

TEST(ModelLoader, StlCountsItsFacets) {
  REQUIRE_TESTMODELS();
  const std::string file = kModels + "STL/Spider_ascii.stl";
  const ModelMesh ascii = load_model(file);
  expect_faces(ascii, count_statements(file, "  facet"));
  const ModelMesh binary = load_model(kModels + "STL/Spider_binary.stl");
  EXPECT_EQ(binary.faces.size(), ascii.faces.size());
  EXPECT_FALSE(ascii.faces[0].has_colour);  // STL has no materials: the subobject's colour applies
}

TEST(ModelLoader, PlyAndOffHeadersGiveTheCounts) {
  REQUIRE_TESTMODELS();
  const std::string ply = kModels + "PLY/cube.ply";
  const ModelMesh cube = load_model(ply);
  expect_faces(cube, header_count(ply, "element face"));
  EXPECT_EQ(cube.vertices.size(), header_count(ply, "element vertex"));
  EXPECT_EQ(cube.faces[0].indices.size(), 4u);  // convex quads stay whole
  EXPECT_EQ(bounds(cube).lo, glm::dvec3(0));
  EXPECT_EQ(bounds(cube).hi, glm::dvec3(1));
  const std::string off = kModels + "OFF/Cube.off";
  std::istringstream header(text_of(off));
  std::string magic;
  std::size_t vertices = 0, faces = 0;
  header >> magic >> vertices >> faces;
  const ModelMesh offcube = load_model(off);
  expect_faces(offcube, faces);
  EXPECT_EQ(offcube.vertices.size(), vertices);
  EXPECT_EQ(bounds(offcube).hi, glm::dvec3(0.5));
}

TEST(ModelLoader, Ac3dSumsItsSurfaces) {
  REQUIRE_TESTMODELS();
  const std::string file = kModels + "AC/Wuson.ac";
  const ModelMesh m = load_model(file);
  expect_faces(m, header_count(file, "numsurf "));
  // The same model as OBJ, PLY, STL and OFF: the same polygons and shared vertices.
  for (const char* other : {"OBJ/WusonOBJ.obj", "PLY/Wuson.ply", "STL/Wuson.stl", "OFF/Wuson.off"}) {
    const ModelMesh o = load_model(kModels + other);
    EXPECT_EQ(o.faces.size(), m.faces.size()) << other;
    EXPECT_EQ(o.vertices.size(), m.vertices.size()) << other;
  }
}

TEST(ModelLoader, Gltf2AccessorsGiveTheCountsAndBounds) {
  REQUIRE_TESTMODELS();
  for (const char* file :
       {"glTF2/BoxTextured-glTF/BoxTextured.gltf", "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb"}) {
    const ModelMesh m = load_model(kModels + file);
    const auto gltf = nlohmann::json::parse(text_of(kModels + "glTF2/BoxTextured-glTF/BoxTextured.gltf"));
    const auto& prim = gltf["meshes"][0]["primitives"][0];
    const auto& position = gltf["accessors"][prim["attributes"]["POSITION"].get<int>()];
    expect_faces(m, gltf["accessors"][prim["indices"].get<int>()]["count"].get<std::size_t>() / 3);
    // A cube centred on its node's origin: the node's rotation keeps its bounds.
    EXPECT_EQ(bounds(m).lo.x, position["min"][0].get<double>()) << file;
    EXPECT_EQ(bounds(m).hi.z, position["max"][2].get<double>()) << file;
  }
}

TEST(ModelLoader, ColladaAndObjTriangulateA66Gon) {
  REQUIRE_TESTMODELS();
  for (const char* file : {"Collada/ConcavePolygon.dae", "OBJ/concave_polygon.obj"}) {
    const ModelMesh m = load_model(kModels + file);
    EXPECT_EQ(m.summary.faces, 1u) << file;  // <vcount>66 </vcount>; one 'f' of 66 corners
    EXPECT_EQ(m.summary.triangulated_faces, 1u) << file;
    EXPECT_EQ(m.summary.triangles, 64u) << file;  // n - 2
    EXPECT_EQ(m.faces.size(), 64u) << file;
    EXPECT_TRUE(m.faces[0].has_colour) << file;
    ModelOptions refuse;
    refuse.triangulate = false;
    EXPECT_THROW(load_model(kModels + file, refuse), InputError) << file;
  }
}

TEST(ModelLoader, ThreeDsAndFbxCubes) {
  REQUIRE_TESTMODELS();
  // Two cubes: 6 sides of two triangles each, 8 corners.
  for (const char* file : {"3DS/RotatingCube.3DS", "FBX/box.fbx"}) {
    const ModelMesh m = load_model(kModels + file);
    EXPECT_EQ(m.faces.size(), 12u) << file;
    EXPECT_EQ(m.vertices.size(), 8u) << file;
  }
  // A mirroring node transform: the winding is turned back, so every cube stays a closed solid
  // seen from outside (each edge used once each way).
  const ModelMesh mirrored = load_model(kModels + "FBX/cubes_with_mirroring_and_pivot.fbx");
  EXPECT_GT(mirrored.faces.size(), 0u);
}

TEST(ModelLoader, UpYTurnsTheModelsYIntoZ) {
  REQUIRE_TESTMODELS();
  const ModelMesh z = load_model(kModels + "OBJ/WusonOBJ.obj");
  ModelOptions up;
  up.y_up = true;
  const ModelMesh y = load_model(kModels + "OBJ/WusonOBJ.obj", up);
  ASSERT_EQ(y.vertices.size(), z.vertices.size());
  EXPECT_EQ(bounds(y).lo.z, bounds(z).lo.y);
  EXPECT_EQ(bounds(y).hi.z, bounds(z).hi.y);
  EXPECT_EQ(bounds(y).lo.y, -bounds(z).hi.z);
  EXPECT_EQ(y.faces.size(), z.faces.size());
}

// A scene names a model with 'model' (or 'obj'), a unit, an up axis; a material's colour applies
// unless the subobject gives its own.
TEST(ModelLoader, SceneFieldsApply) {
  REQUIRE_TESTMODELS();
  const auto scene = [](const std::string& fields) {
    return R"({"format": "cig-scene", "version": 1, "channels": [{"fov": 40}],
      "observer": {"keyframes": [{"frame": 0, "position": [0, -10, 2]}]},
      "objects": [{"subobjects": [{"model": "/usr/share/assimp/models/OBJ/box.obj")" +
           fields + "}]}]}";
  };
  const Scene plain = parse_scene(scene(""), "s.json");
  const Scene cm = parse_scene(scene(R"(, "unit": "cm", "up": "y", "colour": [0, 0, 1])"), "s.json");
  const Subobject& a = plain.objects[0].subobjects[0];
  const Subobject& b = cm.objects[0].subobjects[0];
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  EXPECT_DOUBLE_EQ(b.vertices[0].z, 0.01 * a.vertices[0].y);
  EXPECT_EQ(b.polygons[0].colour, Rgb(0, 0, 1));
  EXPECT_EQ(a.model_field, "model");
  EXPECT_EQ(a.model_summary.faces, 6u);
}

}  // namespace
}  // namespace cig
