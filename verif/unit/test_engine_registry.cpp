// The engine registry's tables (registry/engine_registry.hpp), which `cig engines` lists and the
// engines' parsers use, against the engines themselves:
//  * every key an engine lists is accepted at its stated default (or, unset by default, at its
//    lowest value) and at each of its choices, and a value outside its stated range is refused;
//  * a key an engine does not list is refused, whatever other engine takes it;
//  * what the row says an engine draws agrees with the engine (rendering pipelines);
//  * every engine's report carries "dropped" with exactly the keys it documents, in their order,
//    for one image, for rendering pipelines and for a polygon list.
// And stage F on a scene mixing a convex polyhedron with ordinary objects and light points
// (scenes/small/mixed.json): the report counts the frame's polygons that are not faces of a
// polyhedron and its light points; a channel that sees no polyhedron is drawn as background with
// every polygon counted; a scene without polyhedra is refused before any work.
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "generator/image_generator.hpp"
#include "registry/engine_registry.hpp"
#include "scene/scene_loader.hpp"

namespace cig {
namespace {

using Kind = EngineOptionSpec::Kind;

EngineOptions with(const EngineInfo& e, const std::string& key, const std::string& value) {
  EngineOptions o;
  o.snap = e.can.reference;  // the float reference's subpixel= needs --snap
  o.params[key] = value;
  return o;
}

std::string number(double v) { return std::to_string(static_cast<long long>(v)); }

// Values outside a key's stated range.
std::vector<std::string> outside(const EngineOptionSpec& s) {
  switch (s.kind) {
    case Kind::kChoice:
      return {"", "none-of-" + s.choices.front()};
    case Kind::kInteger:
      return {number(s.min - 1), number(s.max + 1), "x"};
    case Kind::kReal:
      return {number(s.min), std::to_string(s.max * 2), "nan", "1x"};
    case Kind::kSyntax:
      return {"", "?"};
  }
  return {};
}

TEST(EngineRegistry, EveryListedKeyTakesItsDefaultAndRefusesValuesOutsideItsRange) {
  for (const EngineInfo& e : engine_infos())
    for (const EngineOptionSpec& s : e.options) {
      SCOPED_TRACE(e.name + " " + s.key + "=" + s.range());
      const std::string at_default = s.default_value.empty() ? number(s.min) : s.default_value;
      EXPECT_NO_THROW(make_engine(e.name, with(e, s.key, at_default)));
      for (const std::string& v : s.choices) EXPECT_NO_THROW(make_engine(e.name, with(e, s.key, v))) << v;
      if (s.kind == Kind::kInteger || s.kind == Kind::kReal) {
        EXPECT_NO_THROW(make_engine(e.name, with(e, s.key, number(s.max))));
      }
      for (const std::string& v : outside(s)) EXPECT_THROW(make_engine(e.name, with(e, s.key, v)), InputError) << v;
    }
}

TEST(EngineRegistry, RefusesEveryKeyItDoesNotList) {
  std::set<std::string> keys{"bogus"};
  for (const EngineInfo& e : engine_infos())
    for (const EngineOptionSpec& s : e.options) keys.insert(s.key);
  for (const EngineInfo& e : engine_infos()) {
    std::set<std::string> listed;
    for (const EngineOptionSpec& s : e.options) listed.insert(s.key);
    for (const std::string& key : keys) {
      if (listed.count(key)) continue;
      // A value some other engine takes for the key, so that only the key can be refused.
      std::string value = "1";
      for (const EngineInfo& other : engine_infos())
        for (const EngineOptionSpec& s : other.options)
          if (s.key == key && !s.default_value.empty()) value = s.default_value;
      EXPECT_THROW(make_engine(e.name, with(e, key, value)), InputError) << e.name << " " << key << "=" << value;
    }
  }
}

TEST(EngineRegistry, RowsAgreeWithTheEngines) {
  ASSERT_EQ(engine_infos().size(), engine_names().size());
  for (const EngineInfo& e : engine_infos()) {
    SCOPED_TRACE(e.name);
    const auto engine = make_engine(e.name, {});
    EXPECT_EQ(engine->name(), e.name);
    EXPECT_EQ(engine->renders_parts(), e.can.pipelines);
    EXPECT_NE(e.can.polygons, e.can.polyhedra);  // stage F draws polyhedra, every other engine polygons
    ASSERT_EQ(engine->drop_kinds().size(), e.drops.size());
    EngineOptions snap;
    snap.snap = true;
    if (e.can.reference) EXPECT_NO_THROW(make_engine(e.name, snap));
    else EXPECT_THROW(make_engine(e.name, snap), InputError) << "--snap";
  }
  EXPECT_THROW(engine_info("nonesuch"), InputError);
}

std::vector<std::string> keys_of(const nlohmann::ordered_json& dropped) {
  std::vector<std::string> keys;
  for (auto it = dropped.begin(); it != dropped.end(); ++it) keys.push_back(it.key());
  return keys;
}

std::vector<std::string> documented(const EngineInfo& e) {
  std::vector<std::string> keys;
  for (const DropKind& d : e.drops) keys.push_back(d.key);
  return keys;
}

class MixedScene : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    scene_ = new Scene(load_scene(std::string(CIG_SOURCE_DIR) + "/scenes/small/mixed.json"));
  }
  static void TearDownTestSuite() { delete scene_; }
  static Scene* scene_;
};
Scene* MixedScene::scene_ = nullptr;

TEST_F(MixedScene, EveryReportCarriesTheDroppedKeysItDocuments) {
  const ImageGenerator pipeline(*scene_);
  nlohmann::ordered_json unused;
  ScreenFrame list = pipeline.geometry(0, 0, unused);  // as a polygon list: no polyhedra
  list.polyhedra.clear();
  list.lists_polyhedra = false;
  for (const EngineInfo& e : engine_infos()) {
    SCOPED_TRACE(e.name);
    const std::vector<ChannelOutput> one = pipeline.render(0, {0, 1}, e.name, {}, 1);
    for (const ChannelOutput& co : one) {
      ASSERT_TRUE(co.report["raster"].contains("dropped"));
      EXPECT_EQ(keys_of(co.report["raster"]["dropped"]), documented(e));
    }
    if (e.can.pipelines) {
      EXPECT_EQ(keys_of(pipeline.render(0, {0}, e.name, {}, 1, 2)[0].report["raster"]["dropped"]), documented(e));
    }
    if (e.can.polygons) { EXPECT_EQ(keys_of(make_engine(e.name, {})->render(list).report["dropped"]), documented(e)); }
  }
}

// The polygons of the frame whose object is not a convex polyhedron, from the scene itself.
long ordinary_polygons(const Scene& scene, const ScreenFrame& f) {
  long n = 0;
  for (const ScreenPolygon& p : f.polygons) n += scene.objects[std::size_t(p.object)].polyhedron ? 0 : 1;
  return n;
}

TEST_F(MixedScene, StageFCountsWhatItDoesNotDraw) {
  const ImageGenerator pipeline(*scene_);
  for (const char* engine : {"invparam", "invparam-double"})
    for (int frame : {0, 1})
      for (int channel : {0, 1}) {
        SCOPED_TRACE(std::string(engine) + " frame " + std::to_string(frame) + " channel " + std::to_string(channel));
        nlohmann::ordered_json unused;
        const ScreenFrame f = pipeline.geometry(frame, channel, unused);
        ASSERT_FALSE(f.polyhedra.empty());
        const long ordinary = ordinary_polygons(*scene_, f);
        ASSERT_GT(ordinary, 0);
        ASSERT_LT(ordinary, long(f.polygons.size()));  // some polygons are the box's faces
        ASSERT_GT(f.light_points.size(), 0u);
        const nlohmann::ordered_json d = make_engine(engine, {})->render(f).report["dropped"];
        EXPECT_EQ(d["polygons_not_drawn"].get<long>(), ordinary);
        EXPECT_EQ(d["light_points_not_drawn"].get<long>(), long(f.light_points.size()));
        EXPECT_EQ(d["samples_on_undrawn_faces"].get<long>(), 0);
      }
}

TEST_F(MixedScene, StageFDrawsAChannelWithoutPolyhedraAsBackgroundAndCountsItsPolygons) {
  const ImageGenerator pipeline(*scene_);
  nlohmann::ordered_json unused;
  ScreenFrame f = pipeline.geometry(0, 0, unused);
  f.polyhedra.clear();  // the scene has some, this channel sees none
  ASSERT_TRUE(f.lists_polyhedra);
  const EngineRun run = make_engine("invparam", {})->render(f);
  EXPECT_EQ(run.report["dropped"]["polygons_not_drawn"].get<long>(), long(f.polygons.size()));
  for (std::int32_t id : run.out.ids.id) ASSERT_EQ(id, -1);
}

TEST(StageF, RefusesASceneWithoutPolyhedraBeforeAnyWork) {
  const Scene hut = load_scene(std::string(CIG_SOURCE_DIR) + "/scenes/small/hut.json");
  for (const char* engine : {"invparam", "invparam-double"})
    EXPECT_THROW(make_engine(engine, {})->check_scene(hut), InputError) << engine;
  EXPECT_NO_THROW(make_engine("segment", {})->check_scene(hut));
}

}  // namespace
}  // namespace cig
