// Convex polyhedra for stage F: the loader's rules ("polyhedron": true, scenes/README.md) and the
// eye-space face planes the geometric processor gives stage F (ScreenFrame::polyhedra).
#include <algorithm>
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "generator/image_generator.hpp"
#include "manager/channel_view.hpp"
#include "scene/polyhedron.hpp"
#include "scene/scene_loader.hpp"
#include "scene/world_database.hpp"
#include "test_support.hpp"

namespace cig {
namespace {

std::size_t face_count(const Scene& s) {
  std::size_t n = 0;
  for (const auto& o : s.objects) n += o.hull.faces.size();
  return n;
}

// Every face normal points away from the mean of the object's vertices.
void expect_outward(const Object& o) {
  glm::dvec3 c(0);
  std::size_t n = 0;
  for (const auto& s : o.subobjects)
    for (const auto& v : s.vertices) c += v, ++n;
  c /= double(n);
  for (const auto& f : o.hull.faces) EXPECT_LT(glm::dot(f.normal, c), f.offset) << o.name;
}

// A one-object scene around a model or inline subobject (JSON text of the subobject).
std::string one_object_scene(const std::string& subobject) {
  return R"({"format": "cig-scene", "version": 1, "channels": [{"name": "c", "fov": 40}],
    "observer": {"keyframes": [{"frame": 0, "position": [0, -10, 1]}]},
    "objects": [{"name": "solid", "polyhedron": true, "subobjects": [)" +
         subobject + "]}]}";
}

TEST(PolyhedronLoader, AcceptsTheShippedScene) {
  const Scene s = load_scene(test::source_path("scenes/polyhedra.json"));
  ASSERT_EQ(s.objects.size(), 16u);
  for (const auto& o : s.objects) {
    EXPECT_TRUE(o.polyhedron) << o.name;
    EXPECT_FALSE(o.hull.reoriented) << o.name;
    expect_outward(o);
  }
  EXPECT_EQ(face_count(s), 103u);
  EXPECT_EQ(s.objects.back().name, "crate");
  EXPECT_EQ(s.objects.back().hull.faces.size(), 6u);  // 12 triangles, merged in pairs
  EXPECT_EQ(s.frame_count(), 10);
}

TEST(PolyhedronLoader, AcceptsTheReadmeExample) {
  const auto blocks = test::json_blocks(test::read_file(test::source_path("scenes/README.md")));
  ASSERT_EQ(blocks.size(), 3u);
  // Parsed as if it were scenes/README.md, so that models/crate.obj resolves.
  const Scene s = parse_scene(blocks[1], test::source_path("scenes/README.md"));
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.objects[0].hull.faces.size(), 6u);
  EXPECT_EQ(s.objects[1].hull.faces.size(), 6u);
}

// Real models from Debian's assimp-testmodels: a quad box and a triangulated cube.
TEST(PolyhedronLoader, AcceptsObjBoxes) {
  const std::string dir = "/usr/share/assimp/models/OBJ/";
  ASSERT_TRUE(std::filesystem::exists(dir + "box.obj")) << "install assimp-testmodels (tools/deps.sh)";
  for (const char* model : {"box.obj", "cube_usemtl.obj"}) {
    SCOPED_TRACE(model);
    const Scene s =
        parse_scene(one_object_scene(std::string(R"({"obj": ")") + dir + model + R"(", "scale": 2})"), "obj_box.json");
    const Object& o = s.objects[0];
    ASSERT_EQ(o.hull.faces.size(), 6u);
    expect_outward(o);
    // Every face of a box: an axis direction.
    for (const auto& f : o.hull.faces)
      EXPECT_NEAR(std::max({std::abs(f.normal.x), std::abs(f.normal.y), std::abs(f.normal.z)}), 1, 1e-12);
  }
}

TEST(PolyhedronLoader, ReversesAMeshWoundInward) {
  // Every polygon of this tetrahedron winds counter-clockwise seen from inside.
  const std::string inward = R"({"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
      "polygons": [{"indices": [0, 1, 2]}, {"indices": [0, 3, 1]}, {"indices": [0, 2, 3]}, {"indices": [1, 3, 2]}]})";
  std::string outward = inward;
  for (auto [a, b] : {std::pair<std::string, std::string>{"[0, 1, 2]", "[2, 1, 0]"},
                      {"[0, 3, 1]", "[1, 3, 0]"},
                      {"[0, 2, 3]", "[3, 2, 0]"},
                      {"[1, 3, 2]", "[2, 3, 1]"}})
    outward.replace(outward.find(a), a.size(), b);
  const Scene in = parse_scene(one_object_scene(inward), "tet.json");
  const Scene out = parse_scene(one_object_scene(outward), "tet.json");
  EXPECT_TRUE(in.objects[0].hull.reoriented);
  EXPECT_FALSE(out.objects[0].hull.reoriented);
  // Reversed on load: the polygons are drawn from outside, as the outward mesh's.
  EXPECT_EQ(in.objects[0].subobjects[0].polygons[0].indices, (std::vector<std::uint32_t>{2, 1, 0}));
  expect_outward(in.objects[0]);
  expect_outward(out.objects[0]);
  ASSERT_EQ(in.objects[0].hull.faces.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k)
    EXPECT_NEAR(glm::dot(in.objects[0].hull.faces[k].normal, out.objects[0].hull.faces[k].normal), 1, 1e-12);
}

TEST(PolyhedronLoader, RejectsOpenNonConvexAndWarpedSolids) {
  for (const char* name : {"polyhedron_not_closed", "polyhedron_obj_not_closed", "polyhedron_not_convex",
                           "polyhedron_obj_not_convex", "polyhedron_nonplanar"}) {
    SCOPED_TRACE(name);
    try {
      load_scene(test::source_path(std::string("verif/bad_input/") + name + ".json"));
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) { EXPECT_NE(e.rule().find("polyhedron"), std::string::npos) << e.what(); }
  }
  // The same open box without "polyhedron" is an ordinary object.
  std::string text = test::read_file(test::source_path("verif/bad_input/polyhedron_not_closed.json"));
  text.replace(text.find("\"polyhedron\": true"), 18, "\"polyhedron\": false");
  const Scene s = parse_scene(text, "open_box.json");
  EXPECT_FALSE(s.objects[0].polyhedron);
  EXPECT_TRUE(s.objects[0].hull.faces.empty());
}

// The rule of the InputError loading `text` (as `file`) throws, prefixed by its JSON place.
std::string load_error(const std::string& text, const std::string& file) {
  try {
    parse_scene(text, file);
  } catch (const InputError& e) { return e.where() + ": " + e.rule(); }
  return "accepted";
}

// Not convex: the first edge that turns inward is named, with its polygons and vertices (polygon
// order, then the order of the polygon's corners as listed), wherever the mesh's winding and
// subobjects put them; a model's by mesh and face.
TEST(PolyhedronLoader, NamesTheFirstEdgeThatTurnsInward) {
  const std::string file = test::source_path("verif/bad_input/polyhedron_not_convex.json");
  const nlohmann::json valley = nlohmann::json::parse(test::read_file(file));
  // The valley roof: polygons 2 and 3 are its two halves, meeting in the valley (x = 0, z = 7).
  const std::string edge =
      "the edge from vertex 8 (0, 5, 7) to vertex 3 (0, -5, 7) between polygons 2 and 3 turns "
      "inward (interior dihedral angle 241.9 degrees, more than 180: polygon 3 rises 5.144958 m "
      "above the plane of polygon 2, tolerance ";
  EXPECT_NE(load_error(valley.dump(), file)
                .find("objects[0].subobjects[0].polygons[2]: object 'valley_roof': "
                      "polyhedron is not convex: " +
                      edge),
            std::string::npos)
      << load_error(valley.dump(), file);

  // Wound inward as a whole (reversed at load): the same polygons, the edge as the input lists it.
  nlohmann::json inward = valley;
  for (auto& p : inward["objects"][0]["subobjects"][0]["polygons"]) {
    std::vector<int> ids = p["indices"];
    std::reverse(ids.begin(), ids.end());
    p["indices"] = ids;
  }
  EXPECT_NE(load_error(inward.dump(), file)
                .find("polygons[2]: object 'valley_roof': polyhedron is not convex: the edge from vertex 3 (0, -5, 7) "
                      "to vertex 8 (0, 5, 7) between polygons 2 and 3 turns inward"),
            std::string::npos)
      << load_error(inward.dump(), file);

  // Polygon 3 moved to a subobject of its own: each polygon named with its subobject; the vertex
  // indices are those of the first polygon's subobject.
  nlohmann::json split = valley;
  nlohmann::json& sub = split["objects"][0]["subobjects"];
  nlohmann::json second = sub[0];
  second["polygons"] = nlohmann::json::array({sub[0]["polygons"][3]});
  sub[0]["polygons"].erase(3);
  sub.push_back(second);
  EXPECT_NE(load_error(split.dump(), file)
                .find("objects[0].subobjects[0].polygons[2]: object 'valley_roof': polyhedron is not convex: the edge "
                      "from vertex 8 (0, 5, 7) to vertex 3 (0, -5, 7) between polygon 2 of subobject 0 and polygon 0 "
                      "of subobject 1 turns inward"),
            std::string::npos)
      << load_error(split.dump(), file);

  // A model: its faces by mesh and face in the file, the edge's ends by position (object coordinates).
  const std::string obj = test::source_path("verif/bad_input/polyhedron_obj_not_convex.json");
  EXPECT_NE(load_error(test::read_file(obj), obj)
                .find("objects[0].subobjects[0].obj: model 'models/l_prism.obj' mesh 'defaultobject' face 6: object "
                      "'l_prism': polyhedron is not convex: the edge from (10, 10, 0) to (10, 10, 10) between mesh "
                      "'defaultobject' face 6 and mesh 'defaultobject' face 7 turns inward (interior dihedral angle "
                      "270.0 degrees"),
            std::string::npos)
      << load_error(test::read_file(obj), obj);
}

// Every edge folds outward, but two tetrahedra apart are not one convex solid: the vertex test says so.
TEST(PolyhedronLoader, RejectsPiecesApartThatNoEdgeShows) {
  const std::string tet = R"({"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
      "polygons": [{"indices": [2, 1, 0]}, {"indices": [1, 3, 0]}, {"indices": [3, 2, 0]}, {"indices": [2, 3, 1]}]})";
  std::string apart = tet;
  apart.replace(apart.find("[[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]"), 44,
                "[[5, 0, 0], [6, 0, 0], [5, 1, 0], [5, 0, 1]]");
  EXPECT_EQ(load_error(one_object_scene(tet), "tet.json"), "accepted");
  const std::string e = load_error(one_object_scene(tet + ", " + apart), "two.json");
  EXPECT_NE(e.find("polyhedron is not convex: no edge turns inward, but the vertex"), std::string::npos) << e;
}

// Stage B's planes against its own polygons, frames 0 (100 km) and 9 (1 km) of the shipped scene.
class PolyhedraFrames : public ::testing::TestWithParam<int> {};

// Eye space of stage F: the geometric processor's eye frame with y down.
glm::dvec3 stage_f_eye(const ChannelView& view, const glm::dvec3& world) {
  const glm::dvec3 e = view.to_eye(world);
  return {e.x, -e.y, e.z};
}

TEST_P(PolyhedraFrames, FacesMatchTheDrawnPolygonsAndBoundTheirObjects) {
  const Scene scene = load_scene(test::source_path("scenes/polyhedra.json"));
  const WorldDatabase db = build_world_database(scene);
  const ImageGenerator pipeline(scene);
  const int frame = GetParam();
  int drawn_faces = 0, polyhedra = 0;
  for (int ch = 0; ch < int(scene.channels.size()); ++ch) {
    SCOPED_TRACE("channel " + std::to_string(ch));
    nlohmann::ordered_json report;
    const ScreenFrame f = pipeline.geometry(frame, ch, report);
    const ChannelView view = make_channel_view(scene, frame, ch);
    EXPECT_DOUBLE_EQ(f.tan_half_fov, view.tan_half_fov);
    polyhedra += int(f.polyhedra.size());
    for (const EyePolyhedron& p : f.polyhedra) {
      const Object& o = scene.objects[std::size_t(p.object)];
      ASSERT_EQ(p.faces.size(), o.hull.faces.size());
      // The object's size sets its planarity tolerance; rounding adds ~1e-15 of the coordinates.
      glm::dvec3 lo(1e300), hi(-1e300), centre(0);
      std::size_t n = 0;
      for (const auto& w : db.objects[std::size_t(p.object)].subobjects)
        for (const auto& v : w.vertices) {
          const glm::dvec3 e = stage_f_eye(view, v);
          lo = glm::min(lo, e), hi = glm::max(hi, e), centre += e, ++n;
        }
      centre /= double(n);
      const double reach = std::max(glm::length(lo), glm::length(hi)) + glm::length(hi - lo);
      const double tol = kPolyhedronTolerance * glm::length(hi - lo) + 1e-12 * reach;
      for (const EyeFace& face : p.faces) {
        const glm::dvec3 nrm(face.nx, face.ny, face.nz);
        EXPECT_NEAR(glm::length(nrm), 1, 1e-12);
        EXPECT_LT(glm::dot(nrm, centre) - face.d, 0) << o.name;  // the centre is inside
        if (face.polygon < 0) continue;
        ++drawn_faces;
        ASSERT_LT(std::size_t(face.polygon), f.polygons.size());
        const ScreenPolygon& sp = f.polygons[std::size_t(face.polygon)];
        EXPECT_EQ(sp.object, p.object);
        EXPECT_LT(face.d, 0) << o.name << ": a drawn face faces the eye";
        for (const ScreenVertex& v : sp.vertices) {
          const glm::dvec3 r(v.xs * v.zs * f.tan_half_fov, v.ys * v.zs * f.tan_half_fov, v.zs);
          EXPECT_NEAR(glm::dot(nrm, r), face.d, tol) << o.name << " at depth " << v.zs;
        }
      }
    }
    // Every drawn polygon of a polyhedron lies on a face; faces name the first of them.
    for (std::size_t i = 0; i < f.polygons.size(); ++i) {
      const ScreenPolygon& sp = f.polygons[i];
      const auto it = std::find_if(f.polyhedra.begin(), f.polyhedra.end(),
                                   [&](const EyePolyhedron& p) { return p.object == sp.object; });
      ASSERT_NE(it, f.polyhedra.end());
      const Object& o = scene.objects[std::size_t(sp.object)];
      const EyeFace& face = it->faces[std::size_t(o.hull.face_of[std::size_t(sp.subobject)][std::size_t(sp.polygon)])];
      EXPECT_GE(face.polygon, 0);
      EXPECT_LE(face.polygon, std::int32_t(i));
    }
  }
  EXPECT_GT(polyhedra, 10);
  EXPECT_GT(drawn_faces, 20);
}

INSTANTIATE_TEST_SUITE_P(Frames, PolyhedraFrames, ::testing::Values(0, 9));

TEST(PolyhedronGeometry, PolygonListsAndOrdinaryObjectsHaveNone) {
  const Scene scene = load_scene(test::source_path("scenes/airfield.json"));
  nlohmann::ordered_json report;
  const ScreenFrame f = ImageGenerator(scene).geometry(0, 1, report);
  EXPECT_FALSE(f.polygons.empty());
  EXPECT_TRUE(f.polyhedra.empty());
  EXPECT_TRUE(load_polygon_list(test::source_path("scenes/small/overlap.polys.json")).polyhedra.empty());
}

}  // namespace
}  // namespace cig
