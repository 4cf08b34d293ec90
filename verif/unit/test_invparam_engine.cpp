// Stage F's engines (cmodel/invparam/invparam_engine.hpp) on the polyhedra scene against the float
// reference, which draws the same objects as polygons with a z-buffer: an independent method (edge
// coverage of projected polygons against ray-plane intersections of whole solids).
//  * At W = 64 and in the double twin every pixel shows the reference's polygon and colour, in every
//    channel of frames 3 (10 km) and 9 (1 km).
//  * The word length matters: at 100 km (frame 0, the 0.4-degree channel) 48-bit words give pixels
//    of another polygon (the panel 1 mm in front of the wall and the wall's edges), 64-bit words none.
//  * What stage F cannot draw is refused: a frame without polyhedra, subpixel=, bad bits.
//  * What it cannot draw in a scene it can is counted, not drawn: beside a convex polyhedron, an
//    object that is not one has all its polygons in dropped.polygons_not_drawn (a kind the registry
//    declares "cannot draw", so every command warns of it), per frame, and owns no pixel.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "generator/image_generator.hpp"
#include "image/image_compare.hpp"
#include "registry/engine_registry.hpp"
#include "scene/scene_loader.hpp"

namespace cig {
namespace {

struct Difference {
  int max_abs = 0;
  long ids = 0;
};

Difference difference(const RasterImage& got, const RasterImage& want) {
  const ImageError e = compare_images(got.image, want.image, got.ids, want.ids);
  return {std::max({e.max_abs[0], e.max_abs[1], e.max_abs[2]}), differing_ids(got.ids, want.ids)};
}

EngineOptions with(const std::string& key, const std::string& value) {
  EngineOptions o;
  o.params[key] = value;
  return o;
}

class InvparamScene : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    scene_ = new Scene(load_scene(std::string(CIG_SOURCE_DIR) + "/scenes/polyhedra.json"));
  }
  static void TearDownTestSuite() { delete scene_; }
  static Scene* scene_;
};
Scene* InvparamScene::scene_ = nullptr;

TEST_F(InvparamScene, EqualsTheReferenceAt64BitsAndInTheTwin) {
  const ImageGenerator pipeline(*scene_);
  const std::vector<int> channels{0, 1, 2};
  for (int frame : {3, 9}) {
    const std::vector<ChannelOutput> want = pipeline.render(frame, channels, "float", {}, 1);
    for (const char* engine : {"invparam", "invparam-double"}) {
      const std::vector<ChannelOutput> got = pipeline.render(frame, channels, engine, {}, 1);
      for (std::size_t c = 0; c < channels.size(); ++c) {
        const Difference d = difference(got[c].out, want[c].out);
        EXPECT_EQ(d.ids, 0) << engine << " frame " << frame << " channel " << c;
        EXPECT_LE(d.max_abs, 1) << engine << " frame " << frame << " channel " << c;
        EXPECT_GT(got[c].report["raster"]["samples_hit"].get<long>(), 0) << engine;
      }
    }
  }
}

TEST_F(InvparamScene, ShortWordsLoseThePanelAt100Km) {
  const ImageGenerator pipeline(*scene_);
  const std::vector<int> narrow{2};
  const RasterImage want = pipeline.render(0, narrow, "float", {}, 1)[0].out;
  EXPECT_GT(difference(pipeline.render(0, narrow, "invparam", with("bits", "48"), 1)[0].out, want).ids, 100);
  EXPECT_EQ(difference(pipeline.render(0, narrow, "invparam", with("bits", "64"), 1)[0].out, want).ids, 0);
}

TEST(InvparamEngine, RefusesWhatStageFCannotDraw) {
  ScreenFrame list;  // a polygon list: polygons, no polyhedra
  ScreenPolygon p;
  p.vertices = {{-0.5, -0.5, 10, 1}, {0.5, -0.5, 10, 1}, {0, 0.5, 10, 1}};
  list.polygons.push_back(p);
  for (const char* engine : {"invparam", "invparam-double"}) {
    EXPECT_THROW(make_engine(engine, {})->check_frame(list), InputError) << engine;
    EXPECT_THROW(make_engine(engine, with("subpixel", "2")), InputError) << engine;
  }
  EXPECT_THROW(make_engine("invparam", with("bits", "23")), InputError);
  EXPECT_THROW(make_engine("invparam", with("bits", "x")), InputError);
  EXPECT_THROW(make_engine("invparam-double", with("bits", "64")), InputError);  // the twin has no word
  EXPECT_NO_THROW(make_engine("invparam", with("bits", "57")));
}

// A 10 m box (inline, outward) at x = `x`, as a scene object; `polyhedron`: its "polyhedron" field.
std::string box_object(const std::string& name, double x, bool polyhedron) {
  return R"({"name": ")" + name + R"(", "position": [)" + std::to_string(x) + R"(, 40, 0], "polyhedron": )" +
         (polyhedron ? "true" : "false") + R"(, "subobjects": [{"vertices": [
      [-5, -5, 0], [5, -5, 0], [5, 5, 0], [-5, 5, 0], [-5, -5, 10], [5, -5, 10], [5, 5, 10], [-5, 5, 10]],
      "polygons": [{"indices": [0, 3, 2, 1]}, {"indices": [4, 5, 6, 7]}, {"indices": [0, 1, 5, 4]},
                   {"indices": [1, 2, 6, 5]}, {"indices": [2, 3, 7, 6]}, {"indices": [3, 0, 4, 7]}]}]})";
}

// Two frames of one channel looking north at the objects from 40 m, a little above them.
std::string two_box_scene(const std::string& objects) {
  return R"({"format": "cig-scene", "version": 1, "raster": 64, "channels": [{"name": "c", "fov": 50}],
    "observer": {"keyframes": [{"frame": 0, "position": [0, -5, 12], "pitch": -10},
                               {"frame": 1, "position": [2, -3, 12], "pitch": -10}]},
    "objects": [)" +
         objects + "]}";
}

TEST(InvparamEngine, CountsTheObjectsThatAreNotPolyhedraAsNotDrawn) {
  // What every command warns of: the engine's declared drop kinds, polygons_not_drawn "cannot draw".
  for (const char* engine : {"invparam", "invparam-double"}) {
    const std::vector<DropKind>& kinds = engine_info(engine).drops;
    const auto k =
        std::find_if(kinds.begin(), kinds.end(), [](const DropKind& d) { return d.key == "polygons_not_drawn"; });
    ASSERT_NE(k, kinds.end()) << engine;
    EXPECT_EQ(k->cause, DropKind::Cause::kCannotDraw) << engine;
  }
  const Scene mixed = parse_scene(two_box_scene(box_object("solid", -8, true) + ", " + box_object("plain", 8, false)),
                                  "two_boxes.json");
  ASSERT_TRUE(mixed.objects[0].polyhedron);
  ASSERT_FALSE(mixed.objects[1].polyhedron);
  const ImageGenerator pipeline(mixed);
  for (int frame : {0, 1}) {
    SCOPED_TRACE("frame " + std::to_string(frame));
    nlohmann::ordered_json geometry_report;
    const ScreenFrame list = pipeline.geometry(frame, 0, geometry_report);
    std::vector<char> plain(list.polygons.size(), 0);  // the polygons of the object that is not a polyhedron
    long plain_count = 0, solid_count = 0;
    for (std::size_t i = 0; i < list.polygons.size(); ++i) {
      plain[i] = list.polygons[i].object == 1;
      plain_count += plain[i];
      solid_count += list.polygons[i].object == 0;
    }
    ASSERT_GT(plain_count, 0);  // both objects are in view
    ASSERT_GT(solid_count, 0);
    ASSERT_EQ(list.polyhedra.size(), 1u);
    for (const char* engine : {"invparam", "invparam-double"}) {
      SCOPED_TRACE(engine);
      const ChannelOutput got = pipeline.render(frame, {0}, engine, {}, 1)[0];
      const nlohmann::ordered_json& raster = got.report["raster"];
      EXPECT_EQ(raster["objects"].get<long>(), 1);
      EXPECT_EQ(raster["dropped"]["polygons_not_drawn"].get<long>(), plain_count);
      EXPECT_EQ(raster["dropped"]["light_points_not_drawn"].get<long>(), 0);
      EXPECT_EQ(raster["dropped"]["samples_on_undrawn_faces"].get<long>(), 0);
      EXPECT_GT(raster["samples_hit"].get<long>(), 0);
      // Not drawn: no pixel is the plain box's; the polyhedron's are there.
      long solid_pixels = 0;
      for (std::int32_t id : got.out.ids.id) {
        if (id < 0) continue;
        EXPECT_FALSE(plain[std::size_t(id)]) << "pixel of polygon " << id;
        ++solid_pixels;
      }
      EXPECT_GT(solid_pixels, 0);
    }
    // The float reference draws both (the plain box is in the picture; stage F leaves it out).
    const ChannelOutput want = pipeline.render(frame, {0}, "float", {}, 1)[0];
    EXPECT_TRUE(std::any_of(want.out.ids.id.begin(), want.out.ids.id.end(),
                            [&](std::int32_t id) { return id >= 0 && plain[std::size_t(id)]; }));
  }
  // The polyhedron alone: nothing dropped.
  const Scene alone = parse_scene(two_box_scene(box_object("solid", -8, true)), "one_box.json");
  const ChannelOutput got = ImageGenerator(alone).render(0, {0}, "invparam", {}, 1)[0];
  EXPECT_EQ(got.report["raster"]["dropped"]["polygons_not_drawn"].get<long>(), 0);
}

}  // namespace
}  // namespace cig
