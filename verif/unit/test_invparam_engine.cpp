// Stage F's engines (cmodel/invparam/invparam_engine.hpp) on the polyhedra scene against the float
// reference, which draws the same objects as polygons with a z-buffer: an independent method (edge
// coverage of projected polygons against ray-plane intersections of whole solids).
//  * At W = 64 and in the double twin every pixel shows the reference's polygon and colour, in every
//    channel of frames 3 (10 km) and 9 (1 km).
//  * The word length matters: at 100 km (frame 0, the 0.4-degree channel) 48-bit words give pixels
//    of another polygon (the panel 1 mm in front of the wall and the wall's edges), 64-bit words none.
//  * What stage F cannot draw is refused: a frame without polyhedra, subpixel=, bad bits.
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

}  // namespace
}  // namespace cig
