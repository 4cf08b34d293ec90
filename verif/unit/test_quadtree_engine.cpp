// The quadtree engine as a whole (cmodel/quadtree): its coverage equals the snapped float
// reference's, masks never change the image but do kill hidden polygons before the pixel level,
// and the architecture only changes the cycles, never the image.
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "engine/engine.hpp"
#include "frame/screen_frame.hpp"
#include "generator/image_generator.hpp"
#include "image/image_compare.hpp"
#include "registry/engine_registry.hpp"
#include "scene/scene_loader.hpp"

namespace cig {
namespace {

EngineRun run(const ScreenFrame& f, const std::string& engine, std::map<std::string, std::string> params = {},
              bool snap = false) {
  EngineOptions o;
  o.snap = snap;
  o.params = std::move(params);
  return make_engine(engine, o)->render(f);
}

// The depth-complexity-10 list (screen coordinates, any raster) at 128 lines: the same scene, a
// sixteenth of the samples, so the tests stay fast in the sanitizer build.
ScreenFrame depth10() {
  ScreenFrame f = load_polygon_list(std::string(CIG_SOURCE_DIR) + "/scenes/stress/depth10.polys.json");
  f.raster = 128;
  return f;
}

// In depth10.polys.json the priority order is the depth order everywhere (each polygon lies
// behind the previous one), so a priority engine and the z-buffered reference must agree on the
// visible polygon of every pixel; with the vertices snapped to the formatter grid the coverage
// is the same sample for sample, so the ids must be identical.
TEST(QuadtreeEngine, IdsEqualTheSnappedReferenceWhenPriorityIsDepth) {
  const ScreenFrame f = depth10();
  const EngineRun q = run(f, "quadtree");
  const EngineRun r = run(f, "float", {}, true);
  EXPECT_EQ(differing_ids(q.out.ids, r.out.ids), 0);
  const EngineRun s = run(f, "segment");
  EXPECT_EQ(differing_ids(q.out.ids, s.out.ids), 0);  // the segment processor's coverage is exact too
}

// On the airfield, where the depth-sorted priority order and the z-buffer do disagree in places,
// the engine's ids equal the snapped reference's with visibility by priority order in every pixel
// (identical coverage, same order), and every pixel where they differ from the z-buffered
// snapped reference is one where that reference changes its polygon when visibility follows the
// priority order. Frame 0, the centre channel, at 256 lines (sanitizer build time).
TEST(QuadtreeEngine, AirfieldIdsDifferFromTheZBufferOnlyWherePriorityDisagrees) {
  const Scene scene = load_scene(std::string(CIG_SOURCE_DIR) + "/scenes/airfield.json");
  ImageGenerator pipeline(scene);
  nlohmann::ordered_json unused;
  ScreenFrame f = pipeline.geometry(0, 1, unused);
  f.raster = 256;
  const EngineRun q = run(f, "quadtree");
  const EngineRun by_priority = run(f, "float", {{"visibility", "priority"}}, true);
  const EngineRun by_depth = run(f, "float", {}, true);
  EXPECT_EQ(differing_ids(q.out.ids, by_priority.out.ids), 0);
  long differ = 0, explained = 0;
  for (std::size_t k = 0; k < q.out.ids.id.size(); ++k)
    if (q.out.ids.id[k] != by_depth.out.ids.id[k]) {
      ++differ;
      explained += by_priority.out.ids.id[k] != by_depth.out.ids.id[k];
    }
  EXPECT_GT(differ, 0);  // the airfield has such pixels: the test would not see a broken classification
  EXPECT_EQ(explained, differ);
}

TEST(QuadtreeEngine, MasksNeverChangeTheImage) {
  const ScreenFrame f = depth10();
  const EngineRun on = run(f, "quadtree", {{"masks", "on"}});
  const EngineRun off = run(f, "quadtree", {{"masks", "off"}});
  EXPECT_EQ(on.out.image.rgb, off.out.image.rgb);
  EXPECT_EQ(on.out.ids.id, off.out.ids.id);
}

// Depth complexity 10: with masks, hidden polygons die before the pixel level, and the work and
// the cycles drop accordingly (counts of the cycle model, deterministic, not timings).
TEST(QuadtreeEngine, HiddenPolygonsDieAboveThePixelLevel) {
  const ScreenFrame f = depth10();
  const EngineRun on = run(f, "quadtree", {{"masks", "on"}});
  const EngineRun off = run(f, "quadtree", {{"masks", "off"}});
  const auto& died = on.report["pieces_hidden_by_level"];
  long hidden = 0;
  for (std::size_t l = 0; l < died.size(); ++l) hidden += died[l].get<long>();
  EXPECT_GT(hidden, long(f.polygons.size()) / 4);   // most of ten layers are hidden
  EXPECT_EQ(died[died.size() - 1].get<long>(), 0);  // none reaches the pixel level
  EXPECT_EQ(off.report["pieces_hidden_by_masks"].get<long>(), 0);
  const long long cycles_on = on.report["cycles"]["frame"].get<long long>();
  const long long cycles_off = off.report["cycles"]["frame"].get<long long>();
  EXPECT_GE(cycles_off, 3 * cycles_on) << "masks on " << cycles_on << " cycles, off " << cycles_off;
  EXPECT_LT(on.report["pixel_records"].get<long long>(), off.report["pixel_records"].get<long long>());
}

TEST(QuadtreeEngine, ArchitectureChangesCyclesNotTheImage) {
  const ScreenFrame f = depth10();
  const EngineRun pipe = run(f, "quadtree", {{"arch", "7p"}});
  long long previous = -1;
  for (const char* arch : {"7s", "6s1p", "5p2t", "3s2s1s1t"}) {
    SCOPED_TRACE(arch);
    const EngineRun other = run(f, "quadtree", {{"arch", arch}});
    EXPECT_EQ(pipe.out.image.rgb, other.out.image.rgb);
    EXPECT_EQ(pipe.out.ids.id, other.out.ids.id);
    const long long c = other.report["cycles"]["frame"].get<long long>();
    EXPECT_GT(c, 0);
    if (std::string(arch) == "7s") previous = c;
  }
  // One PE for every level does every test in sequence: never faster than the pipeline.
  EXPECT_GE(previous, pipe.report["cycles"]["frame"].get<long long>());
}

// The report without its timings and thread count (what must not depend on the workers).
nlohmann::ordered_json counts_of(const nlohmann::ordered_json& report) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (auto it = report.begin(); it != report.end(); ++it) {
    const std::string& key = it.key();
    const bool timing = key.size() >= 3 && key.compare(key.size() - 3, 3, "_ms") == 0;
    if (key == "threads" || (timing && key != "frame_ms" && key != "budget_ms")) continue;
    out[key] = it->is_object() ? counts_of(*it) : *it;
  }
  return out;
}

// --threads: the colour work and the resolve of full pixels on a second worker and the rest of the
// resolve in strips give the same image, ids and cycle counts (every count of the report) as one
// thread, for 2, 3 and 4 workers; one engine renders the frames in a row (its pixel states cleared
// lazily), the fixed engine and its double twin, frames with light points (the airfield, 128 and
// 256 lines) and the depth-complexity list.
TEST(QuadtreeEngine, ThreadsGiveTheSameImageAndCycles) {
  const Scene scene = load_scene(std::string(CIG_SOURCE_DIR) + "/scenes/airfield.json");
  ImageGenerator pipeline(scene);
  nlohmann::ordered_json unused;
  std::vector<ScreenFrame> frames = {pipeline.geometry(0, 1, unused), depth10(), pipeline.geometry(2, 0, unused)};
  frames[0].raster = 128;
  frames[2].raster = 256;
  for (const char* engine : {"quadtree", "quadtree-double"}) {
    EngineOptions one;
    const auto e1 = make_engine(engine, one);
    std::vector<EngineRun> single;
    for (const ScreenFrame& f : frames) single.push_back(e1->render(f));
    for (int threads = 2; threads <= 4; ++threads) {
      EngineOptions many;
      many.threads = threads;
      const auto en = make_engine(engine, many);
      for (std::size_t k = 0; k < frames.size(); ++k) {
        SCOPED_TRACE(std::string(engine) + " frame " + std::to_string(k) + " threads " + std::to_string(threads));
        const EngineRun& a = single[k];
        const EngineRun b = en->render(frames[k]);
        EXPECT_EQ(a.out.image.rgb, b.out.image.rgb);
        EXPECT_EQ(a.out.ids.id, b.out.ids.id);
        EXPECT_EQ(a.report["cycles"]["frame"], b.report["cycles"]["frame"]);
        EXPECT_EQ(counts_of(a.report), counts_of(b.report));
        EXPECT_EQ(b.report["threads"].get<int>(), threads);
      }
    }
    // A fresh engine gives the same frames (nothing kept from the frame before).
    for (std::size_t k = 0; k < frames.size(); ++k) {
      SCOPED_TRACE(std::string(engine) + " fresh frame " + std::to_string(k));
      const EngineRun fresh = make_engine(engine, one)->render(frames[k]);
      EXPECT_EQ(fresh.out.image.rgb, single[k].out.image.rgb);
      EXPECT_EQ(fresh.out.ids.id, single[k].out.ids.id);
    }
  }
}

// The start window (start=bbox, ArchConfig::start_window): every piece starts its subdivision at
// the smallest window holding its bounding box instead of the whole screen. The same windows'
// parameters come out of the same subdivision and reach the pixels in the same order, so the
// image is identical; the PEs above the start window test one child instead of four, so the
// tests and the cycles never grow (pipeline, tree, stacks; masks on and off).
TEST(QuadtreeEngine, StartWindowChangesCyclesNotTheImage) {
  const ScreenFrame f = depth10();
  for (const char* arch : {"7p", "5p2t", "7s"})
    for (const char* masks : {"on", "off"}) {
      SCOPED_TRACE(std::string(arch) + " masks " + masks);
      const EngineRun screen = run(f, "quadtree", {{"arch", arch}, {"masks", masks}, {"start", "screen"}});
      const EngineRun bbox = run(f, "quadtree", {{"arch", arch}, {"masks", masks}, {"start", "bbox"}});
      EXPECT_EQ(screen.out.image.rgb, bbox.out.image.rgb);
      EXPECT_EQ(screen.out.ids.id, bbox.out.ids.id);
      long long tested_screen = 0, tested_bbox = 0, outside = 0;
      for (const auto& l : screen.report["levels"]) tested_screen += l["children_tested"].get<long long>();
      for (const auto& l : bbox.report["levels"]) {
        tested_bbox += l["children_tested"].get<long long>();
        outside += l["children_outside_start"].get<long long>();
      }
      EXPECT_LT(tested_bbox, tested_screen);
      EXPECT_GT(outside, 0);
      EXPECT_LE(bbox.report["cycles"]["frame"].get<long long>(), screen.report["cycles"]["frame"].get<long long>());
    }
}

TEST(QuadtreeEngine, RejectsBadOptions) {
  EngineOptions o;
  o.params = {{"arch", "9q"}};
  EXPECT_THROW(make_engine("quadtree", o), InputError);
  o.params = {{"masks", "maybe"}};
  EXPECT_THROW(make_engine("quadtree", o), InputError);
  o.params = {{"format", "huge"}};
  EXPECT_THROW(make_engine("quadtree", o), InputError);
  o.params = {{"fifo", "0"}};
  EXPECT_THROW(make_engine("quadtree", o), InputError);
  o.params = {{"start", "corner"}};
  EXPECT_THROW(make_engine("quadtree", o), InputError);
  // The level count is checked against the frame's raster: 9 levels for a 64-line raster.
  o.params = {{"arch", "9p"}};
  ScreenFrame f;
  f.raster = 64;
  EXPECT_THROW(make_engine("quadtree", o)->render(f), InputError);
}

}  // namespace
}  // namespace cig
