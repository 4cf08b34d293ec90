// Small golden images, compared pixel for pixel (and id for id) with the float reference's
// output. Regenerate with tools/update_goldens.sh only after a deliberate change.
#include <gtest/gtest.h>

#include "engine/engine.hpp"
#include "generator/image_generator.hpp"
#include "image/image.hpp"
#include "registry/engine_registry.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

namespace cig {
namespace {

void expect_same_image(const Image& got, const std::string& golden_png) {
  const Image want = read_png(test::source_path(golden_png));
  ASSERT_EQ(got.width, want.width);
  ASSERT_EQ(got.height, want.height);
  long differing = 0;
  for (std::size_t i = 0; i < got.rgb.size(); ++i) differing += got.rgb[i] != want.rgb[i];
  EXPECT_EQ(differing, 0) << golden_png;
}

void expect_same_ids(const IdBuffer& got, const std::string& golden_ids) {
  const IdBuffer want = read_ids(test::source_path(golden_ids));
  ASSERT_EQ(got.width, want.width);
  ASSERT_EQ(got.height, want.height);
  EXPECT_EQ(got.id, want.id) << golden_ids;
}

TEST(Golden, PolygonListFloatAndSnapped) {
  const ScreenFrame f = load_polygon_list(test::source_path("scenes/small/overlap.polys.json"));
  for (bool snap : {false, true}) {
    EngineOptions o;
    o.snap = snap;
    EngineRun run = make_engine("float", o)->render(f);
    const std::string base = snap ? "verif/golden/overlap_snap" : "verif/golden/overlap";
    expect_same_image(run.out.image, base + ".png");
    expect_same_ids(run.out.ids, base + ".ids");
  }
}

TEST(Golden, SceneThroughManagerGeometryAndReference) {
  const Scene s = load_scene(test::source_path("scenes/small/hut.json"));
  ImageGenerator pipeline(s);
  for (int frame : {0, 3}) {
    auto outs = pipeline.render(frame, {0, 1}, "float", EngineOptions{}, 2);
    for (const auto& co : outs) {
      char base[64];
      std::snprintf(base, sizeof base, "verif/golden/hut_frame_%04d_ch%d", frame, co.channel);
      expect_same_image(co.out.image, std::string(base) + ".png");
      expect_same_ids(co.out.ids, std::string(base) + ".ids");
    }
  }
}

TEST(Golden, PolygonListRoundTripsBitForBit) {
  // The geometric processor's output written as cig-polys and read back renders identically.
  const Scene s = load_scene(test::source_path("scenes/small/hut.json"));
  ImageGenerator pipeline(s);
  nlohmann::ordered_json report;
  const ScreenFrame f = pipeline.geometry(2, 1, report);
  const ScreenFrame g = parse_polygon_list(polygon_list_json(f), "roundtrip");
  ASSERT_EQ(f.polygons.size(), g.polygons.size());
  for (std::size_t i = 0; i < f.polygons.size(); ++i)
    for (std::size_t k = 0; k < f.polygons[i].vertices.size(); ++k) {
      EXPECT_EQ(f.polygons[i].vertices[k].xs, g.polygons[i].vertices[k].xs);
      EXPECT_EQ(f.polygons[i].vertices[k].zs, g.polygons[i].vertices[k].zs);
      EXPECT_EQ(f.polygons[i].vertices[k].is, g.polygons[i].vertices[k].is);
    }
  auto eng = make_engine("float", EngineOptions{});
  EXPECT_EQ(eng->render(f).out.image.rgb, eng->render(g).out.image.rgb);
}

}  // namespace
}  // namespace cig
