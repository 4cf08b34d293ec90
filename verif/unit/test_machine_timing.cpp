// The machine in time, checked against independent counts and hand calculations:
//  * MachineTiming: the segment engine's cycle model is fed the kernels' own counts (the segment
//    memory's stored segments, the edge generator's edges), also when the list is split among
//    rendering pipelines;
//  * SegmentGovernor: timing/segment_prediction.hpp by hand, and the segment processor's governor
//    (budget-ms) on the airfield: the largest threshold that fits, code 0 never dropped, `off` inert;
//  * FrameGovernor: generator/frame_governor's visibility range, its learning and list_work;
//  * FrameTiming: studies/frame_timing on hand-written channel reports, and percentile.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "engine/engine.hpp"
#include "frame/screen_frame.hpp"
#include "generator/frame_governor.hpp"
#include "generator/image_generator.hpp"
#include "geometry/geometric_processor.hpp"
#include "manager/channel_view.hpp"
#include "manager/scene_manager.hpp"
#include "registry/engine_registry.hpp"
#include "scene/scene_loader.hpp"
#include "scene/world_database.hpp"
#include "studies/frame_timing.hpp"
#include "studies/operation_counts.hpp"
#include "timing/segment_prediction.hpp"

namespace cig {
namespace {

using json = nlohmann::ordered_json;

const Scene& airfield() {
  static const Scene scene = load_scene(std::string(CIG_SOURCE_DIR) + "/scenes/airfield.json");
  return scene;
}

// Frame 0, the centre channel of the airfield (the one the other engine tests use), as stage B gives it.
const ScreenFrame& airfield_centre() {
  static const ScreenFrame frame = [] {
    ImageGenerator g(airfield());
    json unused;
    return g.geometry(0, 1, unused);
  }();
  return frame;
}

EngineRun segment_run(const ScreenFrame& f, std::map<std::string, std::string> params = {}) {
  EngineOptions o;
  o.params = std::move(params);
  return make_engine("segment", o)->render(f);
}

std::string ms_text(double ms) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", ms);
  return buf;
}

std::uint64_t u64(const json& j) { return j.get<std::uint64_t>(); }

// ---------------------------------------------------------------------------------------------
// MachineTiming: the cycle model's load is what the kernels counted.

TEST(MachineTiming, SegmentLoadIsTheKernelsCounts) {
  ImageGenerator g(airfield());
  const std::vector<ChannelOutput> out = g.render(0, {1}, "segment", EngineOptions{}, 1);
  ASSERT_EQ(out.size(), 1u);
  const json& r = out[0].report["raster"];
  const json& cm = r["cycle_model"];
  ASSERT_EQ(cm["fields"].size(), 2u);

  // The segment memory's own counters (SegmentMemory::used per field bank) against the cycle
  // model's (one count per Y-sorter write into SegmentLoadItem::segments).
  const std::uint64_t even = u64(r["segments"]["stored_even"]), odd = u64(r["segments"]["stored_odd"]);
  ASSERT_GT(even + odd, 1000u);  // a real frame
  EXPECT_EQ(u64(cm["fields"][0]["segments"]), even);
  EXPECT_EQ(u64(cm["fields"][1]["segments"]), odd);
  // A third count: what the generators made less what the full memory refused.
  EXPECT_EQ(even + odd,
            u64(r["segments"]["polygon"]) + u64(r["segments"]["light"]) - u64(r["segments"]["dropped_memory_full"]));

  // The edge generator: every stored edge at seed 001's 10 us.
  const double edges = r["edges"].get<double>();
  ASSERT_GT(edges, 0);
  EXPECT_NEAR(cm["edge_generator_ms"].get<double>(), edges * 10000 * 1e-6, 1e-9 * edges * 1e-2);
  const double back = cm["back_ms"].get<double>();
  EXPECT_DOUBLE_EQ(back, cm["fields"][0]["pass_ms"].get<double>() + cm["fields"][1]["pass_ms"].get<double>());
  EXPECT_DOUBLE_EQ(r["hardware_ms"].get<double>(), std::max(cm["edge_generator_ms"].get<double>(), back));
  // A pass writes each of its segments at 400 ns at least (the Y sorter): a lower bound on each.
  EXPECT_GE(cm["fields"][0]["pass_ms"].get<double>(), double(even) * 400e-6 * (1 - 1e-12));
  EXPECT_GE(cm["fields"][1]["pass_ms"].get<double>(), double(odd) * 400e-6 * (1 - 1e-12));
}

TEST(MachineTiming, PipelinesCycleModelSumsThePartsSegments) {
  ImageGenerator g(airfield());
  const std::vector<ChannelOutput> one = g.render(0, {1}, "segment", EngineOptions{}, 1);
  const std::vector<ChannelOutput> two = g.render(0, {1}, "segment", EngineOptions{}, 1, 2);
  const json& r1 = one[0].report["raster"];
  const json& r2 = two[0].report["raster"];
  ASSERT_EQ(r2["pipelines"].size(), 2u);
  ASSERT_EQ(r2["dropped"]["segments_segment_memory_full"].get<long>(), 0);  // the parts' counts are all stored
  std::uint64_t parts = 0;
  for (const json& p : r2["pipelines"]) {
    EXPECT_GT(u64(p["segments"]), 0u);  // both parts have work
    parts += u64(p["segments"]);
  }
  const json& cm = r2["cycle_model"];
  EXPECT_EQ(u64(cm["fields"][0]["segments"]) + u64(cm["fields"][1]["segments"]), parts);
  EXPECT_DOUBLE_EQ(r2["hardware_ms"].get<double>(),
                   std::max(cm["edge_generator_ms"].get<double>(), cm["back_ms"].get<double>()));
  // The same polygons in one list, nothing dropped in either: the same segments in all.
  ASSERT_EQ(r1["dropped"]["polygons_overload"].get<long>(), 0);
  ASSERT_EQ(r2["dropped"]["polygons_overload"].get<long>(), 0);
  ASSERT_EQ(r1["dropped"]["segments_segment_memory_full"].get<long>(), 0);
  EXPECT_EQ(parts, u64(r1["segments"]["stored_even"]) + u64(r1["segments"]["stored_odd"]));
  // Each part's edge generator forms only its own polygons' edges, in parallel: never more than the whole's.
  EXPECT_LE(cm["edge_generator_ms"].get<double>(), r1["cycle_model"]["edge_generator_ms"].get<double>());
  EXPECT_GT(cm["edge_generator_ms"].get<double>(), 0.0);
}

// ---------------------------------------------------------------------------------------------
// SegmentGovernor: the planned passes (timing/segment_prediction.hpp; default SegmentTimingParams:
// 100 ns clock, 1 header word, 4 clocks a polygon segment, 400 ns a write, queues 4 and 16).

TEST(SegmentGovernor, PlannedPassesByHand) {
  const SegmentTimingParams p;
  // One code-5 record of 4 edge words, 3 + 2 segments (test_segment_cycle_model.cpp's polygon):
  // field 0: read 5 words 500, then per segment 400 generating and 400 writing, pipelined:
  // 500 + 400 + 3 x 400 = 2100; field 1: 500 + 400 + 2 x 400 = 1700.
  std::vector<PlannedRecord> plan{{4, {3, 2}, 5, false}};
  EXPECT_DOUBLE_EQ(planned_back_ns(plan, 16, 5, p), 3800);
  // Below its code it is dropped: its header read, 100 ns a field.
  EXPECT_DOUBLE_EQ(planned_back_ns(plan, 16, 4, p), 200);
  // A light point is never dropped: 2 words (200), 1 clock a segment (100), 400 a write:
  // field 0 200 + 100 + 2 x 400 = 1100, field 1 200 + 100 + 400 = 700; the dropped polygon first.
  plan.push_back({0, {2, 1}, 0, true});
  EXPECT_DOUBLE_EQ(planned_back_ns(plan, 16, 0, p), 100 + 1100 + 100 + 700);
}

// Random frames of records: area codes, edge words, segments per field, a light point now and then.
std::vector<PlannedRecord> random_plan(std::mt19937& rng) {
  std::uniform_int_distribution<int> code(0, 15), edges(2, 40), segs(0, 120), kind(0, 9), count(1, 200);
  std::vector<PlannedRecord> out(std::size_t(count(rng)));
  for (PlannedRecord& r : out) {
    r.light = kind(rng) == 0;
    r.code = r.light ? 0 : code(rng);
    r.edges = r.light ? 0 : std::uint32_t(edges(rng));
    for (int f = 0; f < 2; ++f) r.segments[f] = std::uint32_t(segs(rng)) / (r.light ? 10 : 1);
  }
  return out;
}

TEST(SegmentGovernor, PassesGrowWithTheThresholdAndTheChoiceIsTheLargest) {
  std::mt19937 rng(33);
  const SegmentTimingParams p;
  for (int trial = 0; trial < 200; ++trial) {
    const std::vector<PlannedRecord> plan = random_plan(rng);
    double back[16];  // seed 001's 4-bit area codes
    for (int t = 0; t < 16; ++t) back[t] = planned_back_ns(plan, 16, t, p);
    for (int t = 0; t + 1 < 16; ++t) ASSERT_LE(back[t], back[t + 1]) << "trial " << trial;
    const double budget = double(std::uniform_int_distribution<int>(0, 200000)(rng));
    const int ceiling = std::uniform_int_distribution<int>(0, 15)(rng);
    const int t = governed_threshold(plan, 16, budget, ceiling, p);
    ASSERT_GE(t, 0);
    ASSERT_LE(t, ceiling);
    if (t > 0) { EXPECT_LE(back[t], budget); }
    if (t < ceiling) { EXPECT_GT(back[t + 1], budget); }
  }
}

TEST(SegmentGovernor, ThresholdIsTheLargestThatFitsTheBudget) {
  const ScreenFrame& f = airfield_centre();
  const EngineRun off = segment_run(f);
  const EngineRun wide = segment_run(f, {{"budget-ms", "1000000"}});
  ASSERT_TRUE(wide.report.contains("governor"));
  const json& gw = wide.report["governor"];
  const int memory = gw["memory_threshold"].get<int>();
  // Nothing to govern: the memory's threshold, the image of no budget.
  EXPECT_EQ(memory, off.report["overload"]["threshold"].get<int>());
  EXPECT_EQ(gw["threshold"].get<int>(), memory);
  EXPECT_EQ(gw["polygons_dropped"].get<long>(), 0);
  EXPECT_DOUBLE_EQ(gw["predicted_ms"].get<double>(), gw["predicted_ungoverned_ms"].get<double>());
  EXPECT_FALSE(gw["over_budget"].get<bool>());
  EXPECT_EQ(wide.out.image.rgb, off.out.image.rgb);
  EXPECT_EQ(wide.out.ids.id, off.out.ids.id);
  ASSERT_GE(memory, 3);  // the airfield has polygons of several area codes to drop
  // The records as planned are the records as read: the prediction is the frame's modelled time
  // (no segment memory overflow on this frame).
  ASSERT_EQ(off.report["segments"]["dropped_memory_full"].get<long>(), 0);
  EXPECT_NEAR(gw["predicted_ms"].get<double>(), off.report["cycle_model"]["back_ms"].get<double>(), 1e-9);

  // 60% of the ungoverned time.
  const double budget = 0.6 * off.report["cycle_model"]["back_ms"].get<double>();
  const EngineRun part = segment_run(f, {{"budget-ms", ms_text(budget)}});
  const json& g = part.report["governor"];
  const int t = g["threshold"].get<int>();
  EXPECT_DOUBLE_EQ(g["budget_ms"].get<double>(), budget);
  EXPECT_EQ(g["memory_threshold"].get<int>(), memory);
  EXPECT_LT(t, memory);
  EXPECT_GT(t, 0);
  EXPECT_LE(g["predicted_ms"].get<double>(), budget);
  EXPECT_GT(g["predicted_at_next_threshold_ms"].get<double>(), budget);  // the largest that fits
  // What it dropped: every polygon of codes T + 1 .. memory, counted per code by the engine.
  long dropped = 0;
  for (const json& c : part.report["overload"]["per_area_code"])
    if (c["code"].get<int>() > t && c["code"].get<int>() <= memory) dropped += c["polygons_dropped"].get<long>();
  EXPECT_GT(dropped, 0);
  EXPECT_EQ(g["polygons_dropped"].get<long>(), dropped);
  EXPECT_EQ(part.report["overload"]["polygons_dropped"].get<long>(),
            off.report["overload"]["polygons_dropped"].get<long>() + dropped);
  // The governed frame is on time: its modelled passes are the prediction.
  const double modelled = part.report["cycle_model"]["back_ms"].get<double>();
  EXPECT_DOUBLE_EQ(g["modelled_ms"].get<double>(), modelled);
  EXPECT_NEAR(modelled, g["predicted_ms"].get<double>(), 1e-9);
  EXPECT_NEAR(g["prediction_error"].get<double>(), g["predicted_ms"].get<double>() / modelled - 1, 1e-12);
  EXPECT_FALSE(g["over_budget"].get<bool>());
  EXPECT_LT(modelled, off.report["cycle_model"]["back_ms"].get<double>());
}

TEST(SegmentGovernor, BelowCodeZeroOnlyProtectedPolygonsAreDrawn) {
  const ScreenFrame& f = airfield_centre();
  const EngineRun tiny = segment_run(f, {{"budget-ms", "0.000001"}});
  const json& g = tiny.report["governor"];
  EXPECT_EQ(g["threshold"].get<int>(), 0);
  EXPECT_TRUE(g["over_budget"].get<bool>());
  EXPECT_GT(g["predicted_ms"].get<double>(), 0.000001);
  ASSERT_GT(tiny.report["polygons_protected"].get<long>(), 0);
  // Only code 0 (protected polygons and light points) is in the segment memory.
  ASSERT_EQ(tiny.report["segments"]["dropped_memory_full"].get<long>(), 0);
  const json& code0 = tiny.report["overload"]["per_area_code"][0];
  EXPECT_EQ(u64(tiny.report["segments"]["stored_even"]), u64(code0["segments_even"]));
  EXPECT_EQ(u64(tiny.report["segments"]["stored_odd"]), u64(code0["segments_odd"]));
  // The image is that of the frame without its unprotected polygons (rendered with no budget): the
  // dropped records leave nothing behind. Its polygons renumbered back, the light points' priority
  // positions moved by the polygons taken out before them.
  ASSERT_EQ(tiny.report["frame_memory"]["polygons_overflowed"].get<long>(), 0);
  ScreenFrame kept = f;
  kept.polygons.clear();
  std::vector<std::int32_t> old_id, kept_before(f.polygons.size() + 1, 0);
  for (std::size_t k = 0; k < f.polygons.size(); ++k) {
    kept_before[k + 1] = kept_before[k] + (f.polygons[k].protect ? 1 : 0);
    if (!f.polygons[k].protect) continue;
    kept.polygons.push_back(f.polygons[k]);
    old_id.push_back(std::int32_t(k));
  }
  ASSERT_FALSE(kept.polygons.empty());
  ASSERT_LT(kept.polygons.size(), f.polygons.size());
  for (ScreenLightPoint& l : kept.light_points)
    l.priority = kept_before[std::size_t(std::clamp<std::int32_t>(l.priority, 0, std::int32_t(f.polygons.size())))];
  const EngineRun reference = segment_run(kept);
  EXPECT_EQ(tiny.out.image.rgb, reference.out.image.rgb);
  ASSERT_EQ(tiny.out.ids.id.size(), reference.out.ids.id.size());
  long mismatched = 0, protected_pixels = 0;
  for (std::size_t k = 0; k < tiny.out.ids.id.size(); ++k) {
    const std::int32_t r = reference.out.ids.id[k];
    mismatched += tiny.out.ids.id[k] != (r < 0 ? r : old_id[std::size_t(r)]);
    protected_pixels += r >= 0;
  }
  EXPECT_EQ(mismatched, 0);
  EXPECT_GT(protected_pixels, 0);  // protected polygons are drawn
  EXPECT_EQ(tiny.report["segments"]["polygon"], reference.report["segments"]["polygon"]);
  EXPECT_EQ(tiny.report["segments"]["light"], reference.report["segments"]["light"]);
}

TEST(SegmentGovernor, BudgetOffIsNoGovernor) {
  const ScreenFrame& f = airfield_centre();
  const EngineRun none = segment_run(f);
  const EngineRun off = segment_run(f, {{"budget-ms", "off"}});
  EXPECT_FALSE(none.report.contains("governor"));
  EXPECT_FALSE(off.report.contains("governor"));
  EXPECT_EQ(off.out.image.rgb, none.out.image.rgb);
  EXPECT_EQ(off.out.ids.id, none.out.ids.id);
  EXPECT_EQ(off.report["cycle_model"], none.report["cycle_model"]);
  EXPECT_EQ(off.report["overload"], none.report["overload"]);
}

// ---------------------------------------------------------------------------------------------
// FrameGovernor.

bool same_polygons(const ScreenFrame& a, const ScreenFrame& b) {
  if (a.polygons.size() != b.polygons.size() || a.light_points.size() != b.light_points.size()) return false;
  for (std::size_t k = 0; k < a.polygons.size(); ++k) {
    const ScreenPolygon &p = a.polygons[k], &q = b.polygons[k];
    if (p.object != q.object || p.subobject != q.subobject || p.polygon != q.polygon ||
        p.vertices.size() != q.vertices.size())
      return false;
    for (std::size_t v = 0; v < p.vertices.size(); ++v)
      if (p.vertices[v].xs != q.vertices[v].xs || p.vertices[v].ys != q.vertices[v].ys ||
          p.vertices[v].zs != q.vertices[v].zs || p.vertices[v].is != q.vertices[v].is)
        return false;
  }
  return true;
}

TEST(FrameGovernor, HugeBudgetCutsNothing) {
  ImageGenerator g(airfield());
  const FrameGovernor governor(1e6, true, 3);
  json plain, governed;
  const ScreenFrame a = g.geometry(0, 1, plain);
  const ScreenFrame b = g.geometry(0, 1, governed, &governor);
  EXPECT_FALSE(plain.contains("governor"));
  ASSERT_TRUE(governed.contains("governor"));
  const json& r = governed["governor"];
  EXPECT_FALSE(r["range_cut"].get<bool>());
  EXPECT_EQ(r["range"], r["range_ungoverned"]);
  EXPECT_EQ(r["objects_cut"].get<long>(), 0);
  EXPECT_DOUBLE_EQ(r["predicted_ms"].get<double>(), r["predicted_ungoverned_ms"].get<double>());
  EXPECT_TRUE(same_polygons(a, b));
  // Before any frame: B and the edge generator at 10 us per front-facing corner.
  EXPECT_NEAR(r["predicted_ms"].get<double>(), r["front_corners"].get<double>() * 0.01, 1e-9);
  EXPECT_LE(r["front_corners"].get<std::uint64_t>(), r["corners"].get<std::uint64_t>());
  EXPECT_EQ(r["objects_kept"].get<std::uint64_t>(), u64(plain["scene_manager"]["culling"]["objects_kept"]));
}

TEST(FrameGovernor, SmallBudgetShortensTheRange) {
  ImageGenerator g(airfield());
  const FrameGovernor probe(1e6, true, 3);
  json wide;
  const ScreenFrame all = g.geometry(0, 1, wide, &probe);
  const double ungoverned = wide["governor"]["predicted_ungoverned_ms"].get<double>();
  ASSERT_GT(ungoverned, 0);

  const double budget = 0.5 * ungoverned;
  const FrameGovernor governor(budget, true, 3);
  json rep;
  const ScreenFrame cut = g.geometry(0, 1, rep, &governor);
  const json& r = rep["governor"];
  EXPECT_TRUE(r["range_cut"].get<bool>());
  ASSERT_TRUE(r["range"].is_number());
  const double range = r["range"].get<double>();
  if (r["range_ungoverned"].is_number()) {
    EXPECT_LT(range, r["range_ungoverned"].get<double>());
  } else {
    EXPECT_EQ(r["range_ungoverned"], "none");  // the airfield sets no range: the governor's is the only one
  }
  EXPECT_LT(cut.polygons.size(), all.polygons.size());
  EXPECT_GT(r["objects_cut"].get<long>(), 0);
  const double headroom = r["headroom"].get<double>();
  EXPECT_DOUBLE_EQ(headroom, 0.2);  // the first frame's margin
  const double target = budget / (1 + headroom);
  EXPECT_LE(r["predicted_ms"].get<double>(), target);
  EXPECT_DOUBLE_EQ(r["predicted_ungoverned_ms"].get<double>(), ungoverned);
  // The scene manager ran at the governor's range: its kept objects are the report's.
  EXPECT_EQ(r["objects_kept"].get<std::uint64_t>(), u64(rep["scene_manager"]["culling"]["objects_kept"]));

  // The longest range (to the bisection's metre): a metre further no longer fits. The work there,
  // counted by an independent run of the scene manager: front corners at 10 us each.
  const WorldDatabase db = build_world_database(airfield());
  ChannelView view = make_channel_view(airfield(), 0, 1);
  view.range = range + 1.0;
  SceneManagerStats stats;
  const PriorityList further = manage_channel(db, view, stats);
  const ListWork w = list_work(db, further, view.eye);
  EXPECT_GT(double(w.front_corners) * 0.01, target);
  view.range = range;
  SceneManagerStats at_stats;
  const ListWork at = list_work(db, manage_channel(db, view, at_stats), view.eye);
  EXPECT_EQ(at.front_corners, r["front_corners"].get<std::uint64_t>());
  EXPECT_NEAR(r["predicted_ms"].get<double>(), double(at.front_corners) * 0.01, 1e-9);
}

TEST(FrameGovernor, LearningRaisesTheHeadroom) {
  ImageGenerator g(airfield());
  FrameGovernor governor(1e6, true, 3);
  json first;
  g.geometry(0, 1, first, &governor);
  const GovernorDecision d = FrameGovernor::decision_of(first["governor"]);
  EXPECT_DOUBLE_EQ(d.headroom, 0.2);
  ASSERT_GT(d.predicted_ms, 0);
  // Stage B took 2.5 times the prediction: the headroom becomes 1.5, and B's cost 2.5 times the default.
  governor.learn(1, d, 0.0, 2.5 * d.predicted_ms, 0.5 * d.predicted_ms, 1e9);
  json second;
  g.geometry(0, 1, second, &governor);
  const json& r = second["governor"];
  EXPECT_NEAR(r["headroom"].get<double>(), 1.5, 1e-12);
  EXPECT_NEAR(r["predicted_ms"].get<double>(), 2.5 * d.predicted_ms, 1e-9 * d.predicted_ms);
  // A cheaper frame after it changes neither (headroom: the largest seen; costs: a peak hold). The
  // raster's time is ignored (raster_governs_itself).
  governor.learn(1, FrameGovernor::decision_of(r), 0.0, 0.1 * d.predicted_ms, 0.1 * d.predicted_ms, 1e9);
  json third;
  g.geometry(0, 1, third, &governor);
  EXPECT_NEAR(third["governor"]["headroom"].get<double>(), 1.5, 1e-12);
  EXPECT_NEAR(third["governor"]["predicted_ms"].get<double>(), 2.5 * d.predicted_ms, 1e-9 * d.predicted_ms);
  // Another channel keeps the default costs but shares the headroom.
  json other;
  g.geometry(0, 0, other, &governor);
  EXPECT_NEAR(other["governor"]["headroom"].get<double>(), 1.5, 1e-12);
  EXPECT_NEAR(other["governor"]["predicted_ms"].get<double>(), other["governor"]["front_corners"].get<double>() * 0.01,
              1e-9);
}

TEST(FrameGovernor, ReportRoundTrips) {
  GovernorDecision d;
  d.predicted_ms = 3.25, d.predicted_ungoverned_ms = 7.5, d.range = 1200, d.range_ungoverned = HUGE_VAL;
  d.objects_kept = 12, d.objects_cut = 4, d.work.corners = 90, d.work.front_corners = 40, d.range_cut = true;
  d.headroom = 0.35;
  const json r = FrameGovernor::report(d);
  EXPECT_EQ(r["range_ungoverned"], "none");
  const GovernorDecision e = FrameGovernor::decision_of(r);
  EXPECT_EQ(e.predicted_ms, 3.25);
  EXPECT_EQ(e.predicted_ungoverned_ms, 7.5);
  EXPECT_EQ(e.range, 1200);
  EXPECT_TRUE(std::isinf(e.range_ungoverned));
  EXPECT_EQ(e.objects_kept, 12u);
  EXPECT_EQ(e.objects_cut, 4u);
  EXPECT_EQ(e.work.corners, 90u);
  EXPECT_EQ(e.work.front_corners, 40u);
  EXPECT_TRUE(e.range_cut);
  EXPECT_EQ(e.headroom, 0.35);
}

// One subobject of two quads at depth 10 and 12 (world y), the first counter-clockwise seen from
// the eye (facing it), the second wound the other way (facing away); optionally a light point.
Scene two_quads(bool light) {
  json object = {
      {"name", "pair"},
      {"subobjects",
       json::array(
           {{{"name", "faces"},
             {"colour", {0.5, 0.5, 0.5}},
             {"vertices",
              {{-1, 10, -1}, {1, 10, -1}, {1, 10, 1}, {-1, 10, 1}, {-1, 12, -1}, {1, 12, -1}, {1, 12, 1}, {-1, 12, 1}}},
             {"polygons", json::array({{{"indices", {0, 1, 2, 3}}}, {{"indices", {4, 7, 6, 5}}}})}}})}};
  if (light)
    object["light_points"] = {{{"position", {0, 20, 0}}, {"diameter", 0.3}, {"colour", {1, 1, 1}}, {"intensity", 0.8}}};
  const json scene = {{"format", "cig-scene"},
                      {"version", 1},
                      {"raster", 64},
                      {"channels", json::array({{{"name", "c"}, {"fov", 40}}})},
                      {"observer", {{"keyframes", json::array({{{"frame", 0}, {"position", {0, 0, 0}}}})}}},
                      {"objects", json::array({object})}};
  return parse_scene(scene.dump(), "two_quads.json");
}

TEST(FrameGovernor, ListWorkCountsCornersAndFrontCorners) {
  for (const bool light : {false, true}) {
    const Scene scene = two_quads(light);
    const WorldDatabase db = build_world_database(scene);
    const ChannelView view = make_channel_view(scene, 0, 0);
    SceneManagerStats ms;
    const PriorityList list = manage_channel(db, view, ms);
    ASSERT_EQ(list.objects.size(), 1u);
    const ListWork w = list_work(db, list, view.eye);
    EXPECT_EQ(w.corners, light ? 9u : 8u);        // 4 + 4 corners (+ the light point)
    EXPECT_EQ(w.front_corners, light ? 5u : 4u);  // the facing quad's 4 (+ the light point)
    // Stage B agrees on which one faces the eye.
    GeometryStats gs;
    const ScreenFrame f = process_channel(scene, db, view, list, gs);
    EXPECT_EQ(gs.backfacing, 1u);
    EXPECT_EQ(f.polygons.size(), 1u);
    // Seen from behind (the eye at depth 20, beyond both), the other quad faces it.
    const ListWork behind = list_work(db, list, glm::dvec3(0, 20, 0));
    EXPECT_EQ(behind.corners, w.corners);
    EXPECT_EQ(behind.front_corners, light ? 5u : 4u);
  }
}

// ---------------------------------------------------------------------------------------------
// FrameTiming.

// A channel report as ImageGenerator::render writes it (only the keys frame_timing reads).
json segment_channel_report(const std::string& culling_method) {
  return {{"channel", 2},
          {"scene_manager",
           {{"objects", 50},
            {"objects_visible", 8},
            {"subobjects_tested", 24},
            {"occlusion_groups", {{"objects_in_groups_of_2_or_more", 2}}},
            {"culling", {{"method", culling_method}, {"objects_kept", 10}}}}},
          {"geometry", {{"timing", {{"ms", 3.5}}}}},
          {"raster",
           {{"hardware_ms", 99.0},  // not read: the segment processor's stages come from its cycle model
            {"cycle_model",
             {{"edge_generator_ms", 4.25},
              {"back_ms", 12.0},
              {"fields", json::array({{{"video_busy_ms", 1.5}}, {{"video_busy_ms", 2.0}}})},
              {"underrun_lines", 3}}}}}};
}

// Stage A by the counted model for the structure the report gives: the objects sent, Noc the
// objects in groups of 2 or more, Npl = subobjects tested / objects visible = 24 / 8 = 3, Np = 4.
double manager_ms_of(std::uint64_t objects, double clock_mhz) {
  ManagerStructure s;
  s.objects = objects;
  s.occluded = 2;
  s.planes = 3;
  s.points = 4;
  CapacityQuestion q;
  q.clock_mhz = clock_mhz;
  return frame_cycles(q, s) / (clock_mhz * 1e3);
}

TEST(FrameTiming, SegmentChannelStages) {
  const MachineTimingParams p;
  const ChannelTiming c = time_channel(segment_channel_report("line-of-sight"), 512, p);
  const double a = manager_ms_of(10, 100);  // the quadtree's 10 kept objects, not the 50
  ASSERT_GT(a, 0);
  ASSERT_LT(a, 3.5);  // so that the other stages decide below
  EXPECT_EQ(c.channel, 2);
  EXPECT_NEAR(c.stages.a_ms, a, 1e-12);
  EXPECT_DOUBLE_EQ(c.geometry_ms, 3.5);
  EXPECT_DOUBLE_EQ(c.edge_generator_ms, 4.25);
  EXPECT_DOUBLE_EQ(c.stages.b_ms, 4.25);  // the edge generator beside stage B, the slower
  EXPECT_DOUBLE_EQ(c.stages.raster_ms, 12.0);
  EXPECT_DOUBLE_EQ(c.stages.video_ms, 3.5);  // 1.5 + 2.0
  EXPECT_EQ(c.underrun_lines, 3);
  EXPECT_DOUBLE_EQ(c.frame_ms, 12.0);
  EXPECT_NEAR(c.transport_ms, a + 4.25 + 12.0 + 3.5, 1e-12);
  EXPECT_EQ(c.limiting, "raster");

  // Without the quadtree the host sends every object; a slower clock stretches A.
  const ChannelTiming brute = time_channel(segment_channel_report("brute-force"), 512, p);
  EXPECT_NEAR(brute.stages.a_ms, manager_ms_of(50, 100), 1e-12);
  EXPECT_GT(brute.stages.a_ms, c.stages.a_ms);
  MachineTimingParams slow = p;
  slow.manager_clock_mhz = 50;
  EXPECT_NEAR(time_channel(segment_channel_report("line-of-sight"), 512, slow).stages.a_ms, 2 * a, 1e-12);
  // A stage A slow enough to limit: a 0.001 MHz manager.
  slow.manager_clock_mhz = 0.001;
  const ChannelTiming a_bound = time_channel(segment_channel_report("line-of-sight"), 512, slow);
  ASSERT_GT(a_bound.stages.a_ms, 12.0);
  EXPECT_EQ(a_bound.limiting, "A");
  EXPECT_DOUBLE_EQ(a_bound.frame_ms, a_bound.stages.a_ms);

  // B limits when the geometric processor is slower than everything.
  json r = segment_channel_report("line-of-sight");
  r["geometry"]["timing"]["ms"] = 30.0;
  const ChannelTiming b_bound = time_channel(r, 512, p);
  EXPECT_DOUBLE_EQ(b_bound.stages.b_ms, 30.0);
  EXPECT_EQ(b_bound.limiting, "B");
  EXPECT_DOUBLE_EQ(b_bound.frame_ms, 30.0);
  // The video channel's reads.
  r = segment_channel_report("line-of-sight");
  r["raster"]["cycle_model"]["fields"][1]["video_busy_ms"] = 15.0;
  const ChannelTiming v_bound = time_channel(r, 512, p);
  EXPECT_DOUBLE_EQ(v_bound.stages.video_ms, 16.5);
  EXPECT_EQ(v_bound.limiting, "video");
}

TEST(FrameTiming, FrameBufferEngineStages) {
  const MachineTimingParams p;
  const json r = {{"channel", 0},
                  {"geometry", {{"timing", {{"ms", 2.0}}}}},
                  {"raster", {{"engine", "quadtree"}, {"hardware_ms", 5.0}}}};
  // 512 x 512 pixels at 10 ns: 2.62144 ms.
  const ChannelTiming c = time_channel(r, 512, p);
  EXPECT_DOUBLE_EQ(c.stages.a_ms, 0.0);  // no scene manager report
  EXPECT_DOUBLE_EQ(c.stages.b_ms, 2.0);
  EXPECT_DOUBLE_EQ(c.edge_generator_ms, 0.0);
  EXPECT_DOUBLE_EQ(c.stages.raster_ms, 5.0);
  EXPECT_NEAR(c.stages.video_ms, 2.62144, 1e-12);
  EXPECT_EQ(c.underrun_lines, 0);
  EXPECT_DOUBLE_EQ(c.frame_ms, 5.0);
  EXPECT_NEAR(c.transport_ms, 2.0 + 5.0 + 2.62144, 1e-12);
  EXPECT_EQ(c.limiting, "raster");
  // 1024 lines: 10.48576 ms of read-out, the video limits.
  const ChannelTiming big = time_channel(r, 1024, p);
  EXPECT_NEAR(big.stages.video_ms, 10.48576, 1e-12);
  EXPECT_EQ(big.limiting, "video");
  EXPECT_NEAR(big.frame_ms, 10.48576, 1e-12);
  // An empty report: nothing, and no stage slower than A.
  const ChannelTiming empty = time_channel(json::object(), 0, p);
  EXPECT_DOUBLE_EQ(empty.frame_ms, 0.0);
  EXPECT_DOUBLE_EQ(empty.transport_ms, 0.0);
  EXPECT_EQ(empty.limiting, "A");
}

ChannelTiming channel(int id, double frame_ms, double transport_ms, const std::string& limiting,
                      long long underruns = 0) {
  ChannelTiming c;
  c.channel = id;
  c.frame_ms = frame_ms;
  c.transport_ms = transport_ms;
  c.limiting = limiting;
  c.underrun_lines = underruns;
  return c;
}

TEST(FrameTiming, FrameIsTheSlowestChannel) {
  MachineTimingParams p;  // 40 ms budget
  const FrameTiming t =
      time_frame(7, {channel(0, 12, 20, "raster"), channel(1, 15, 18, "B"), channel(2, 9, 30, "A")}, p);
  EXPECT_EQ(t.frame, 7);
  EXPECT_EQ(t.channels.size(), 3u);
  EXPECT_DOUBLE_EQ(t.frame_ms, 15);
  EXPECT_EQ(t.limiting, "B");
  EXPECT_DOUBLE_EQ(t.transport_ms, 30);  // each channel's own pipeline: the longest
  EXPECT_EQ(t.underrun_lines, 0);
  EXPECT_FALSE(t.over_budget);
  p.budget_ms = 14;
  EXPECT_TRUE(time_frame(7, {channel(0, 12, 20, "raster"), channel(1, 15, 18, "B")}, p).over_budget);
  p.budget_ms = 40;
  const FrameTiming u = time_frame(8, {channel(0, 12, 20, "raster", 3), channel(1, 15, 18, "B", 2)}, p);
  EXPECT_EQ(u.underrun_lines, 5);
  EXPECT_TRUE(u.over_budget);  // within the budget but the video underran
  const json j = frame_timing_json(u);
  EXPECT_EQ(j["frame"].get<int>(), 8);
  EXPECT_TRUE(j["over_budget"].get<bool>());
  EXPECT_EQ(j["underrun_lines"].get<long long>(), 5);
  ASSERT_EQ(j["channels"].size(), 2u);
  EXPECT_EQ(j["channels"][1]["limiting"], "B");
  const FrameTiming none = time_frame(0, {}, p);
  EXPECT_DOUBLE_EQ(none.frame_ms, 0);
  EXPECT_FALSE(none.over_budget);
}

TEST(FrameTiming, PercentileByNearestRank) {
  EXPECT_EQ(percentile({4, 2, 3, 1}, 50), 2);  // rank ceil(0.5 x 4) = 2
  EXPECT_EQ(percentile({4, 2, 3, 1}, 51), 3);  // rank ceil(2.04) = 3
  std::vector<double> v;
  for (int k = 100; k >= 1; --k) v.push_back(k);
  EXPECT_EQ(percentile(v, 99), 99);
  EXPECT_EQ(percentile(v, 100), 100);
  EXPECT_EQ(percentile(v, 0), 1);  // rank clamped to 1: the minimum
  EXPECT_EQ(percentile(v, 0.5), 1);
  EXPECT_EQ(percentile({}, 50), 0);
  EXPECT_EQ(percentile({7.5}, 99), 7.5);
}

}  // namespace
}  // namespace cig
