// Seed 000's rendering channels (RasterEngine::render_parts, manager/pipeline_loading.hpp):
//  * engine level: every stress class, with random light points added, cut into 2..5 contiguous
//    parts at random places; each priority engine's merged image and ids equal its image of the
//    whole list (segment, segment-double, quadtree, quadtree-double);
//  * manager level: the pipelines' lists are the channel's priority list cut in order (every run
//    once, each object's light points once), the cuts lie where the loading rule puts them, and
//    `--pipelines 2, 4` render the airfield exactly as one pipeline does;
//  * an engine that does not resolve visibility by priority refuses (InputError);
//  * one image split into strips on 1..4 workers gives the same bits and counts.
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/stress_lists.hpp"
#include "common/error.hpp"
#include "generator/image_generator.hpp"
#include "manager/pipeline_loading.hpp"
#include "registry/engine_registry.hpp"
#include "scene/scene_loader.hpp"

namespace cig {
namespace {

const char* const kPriorityEngines[] = {"segment", "segment-double", "quadtree", "quadtree-double"};

// Random light points over the screen, ranking anywhere in the list.
void add_lights(ScreenFrame& f, std::mt19937_64& rng, int count) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < count; ++k) {
    ScreenLightPoint l;
    l.xs = unit(rng) * 2 - 1;
    l.ys = unit(rng) * 2 - 1;
    l.zs = 1 + unit(rng) * 1000;
    l.ds = 0.002 + unit(rng) * 0.05;
    l.colour = {unit(rng), unit(rng), unit(rng)};
    l.priority = std::int32_t(rng() % (f.polygons.size() + 1));
    f.light_points.push_back(l);
  }
}

// The frame cut before polygons cuts[1..]: part k holds polygons [cuts[k], cuts[k+1]) and the
// lights ranking before one of them (a light ranking after every polygon goes to the last part).
std::vector<ScreenFrame> cut_frame(const ScreenFrame& f, const std::vector<std::size_t>& cuts) {
  std::vector<ScreenFrame> parts;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    ScreenFrame p = f;
    p.polygons.assign(f.polygons.begin() + std::ptrdiff_t(cuts[k]), f.polygons.begin() + std::ptrdiff_t(cuts[k + 1]));
    p.light_points.clear();
    const bool last = k + 2 == cuts.size();
    for (ScreenLightPoint l : f.light_points) {
      const std::size_t at = std::size_t(l.priority);
      if (at < cuts[k] || at > cuts[k + 1] || (at == cuts[k + 1] && !last)) continue;
      l.priority = std::int32_t(at - cuts[k]);
      p.light_points.push_back(l);
    }
    parts.push_back(std::move(p));
  }
  return parts;
}

TEST(RenderingPipelines, StressClassesMergeToTheWholeList) {
  std::mt19937_64 rng(2026);
  int order_matters = 0;  // classes whose parts merged in the wrong order give another image
  for (const std::string& name : cli::stress_class_names()) {
    ScreenFrame whole = cli::make_stress_list(name, 11, 128);
    add_lights(whole, rng, 24);
    const int parts = 2 + int(rng() % 4);
    std::vector<std::size_t> cuts{0};
    for (int k = 1; k < parts; ++k) cuts.push_back(std::size_t(rng() % (whole.polygons.size() + 1)));
    cuts.push_back(whole.polygons.size());
    std::sort(cuts.begin(), cuts.end());
    const std::vector<ScreenFrame> split = cut_frame(whole, cuts);
    for (const char* engine : kPriorityEngines) {
      const auto one = make_engine(engine, {});
      const auto many = make_engine(engine, {});
      ASSERT_TRUE(many->renders_parts());
      const EngineRun a = one->render(whole);
      const EngineRun b = many->render_parts(split);
      EXPECT_TRUE(a.out.image.rgb == b.out.image.rgb) << name << " " << engine << " in " << parts << " parts";
      EXPECT_TRUE(a.out.ids.id == b.out.ids.id) << name << " " << engine << " in " << parts << " parts";
    }
    // The control: the same parts merged last first (the test sees overlaps across the cuts).
    const std::vector<ScreenFrame> reversed(split.rbegin(), split.rend());
    order_matters += make_engine("segment", {})->render_parts(reversed).out.image.rgb !=
                     make_engine("segment", {})->render(whole).out.image.rgb;
  }
  EXPECT_GE(order_matters, 4);
}

TEST(RenderingPipelines, OtherEnginesRefuse) {
  const auto reference = make_engine("float", {});
  EXPECT_FALSE(reference->renders_parts());
  EXPECT_THROW(reference->render_parts({ScreenFrame{}, ScreenFrame{}}), InputError);
}

// The lists' runs, in order, as (object, subobject) pairs and (object) for light points.
struct Flat {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> subobjects;
  std::vector<std::uint32_t> lights;
};
void flatten(const PriorityList& list, Flat& out) {
  for (const PriorityEntry& e : list.objects) {
    if (e.lights) out.lights.push_back(e.object);
    for (std::uint32_t s : list.run(e)) out.subobjects.push_back({e.object, s});
  }
}

TEST(RenderingPipelines, ListsAreTheChannelsListCutInOrder) {
  const Scene scene = load_scene(std::string(CIG_SOURCE_DIR) + "/scenes/airfield.json");
  const WorldDatabase db = build_world_database(scene);
  std::size_t largest_subobject = 0;
  for (const WorldObject& o : db.objects)
    for (const WorldSubobject& s : o.subobjects) largest_subobject = std::max(largest_subobject, s.face_normal.size());
  for (int frame = 0; frame < scene.frame_count(); frame += 7)
    for (int channel = 0; channel < int(scene.channels.size()); ++channel) {
      SceneManagerStats st;
      const PriorityList list = manage_channel(db, make_channel_view(scene, frame, channel), st);
      Flat whole;
      flatten(list, whole);
      for (int n = 1; n <= 7; ++n) {
        const PipelineLoad load = load_pipelines(list, db, n);
        ASSERT_EQ(load.lists.size(), std::size_t(n));
        Flat cut;
        std::uint64_t total = 0;
        for (const PriorityList& l : load.lists) flatten(l, cut);
        for (std::uint64_t p : load.polygons) total += p;
        EXPECT_EQ(cut.subobjects, whole.subobjects) << "frame " << frame << " channel " << channel << " n " << n;
        EXPECT_EQ(cut.lights, whole.lights) << "frame " << frame << " channel " << channel << " n " << n;
        // Each cut within an eighth of a share of its target (a group boundary), or within the
        // largest subobject of it (a cut inside a group, at the nearest subobject boundary).
        const double share = double(total) / n;
        double before = 0;
        for (int k = 0; k + 1 < n; ++k) {
          before += double(load.polygons[std::size_t(k)]);
          EXPECT_LE(std::fabs(before - share * (k + 1)), std::max(share / 8, double(largest_subobject)))
              << "frame " << frame << " channel " << channel << " n " << n << " cut " << k;
        }
      }
    }
}

TEST(RenderingPipelines, AirfieldRendersAsOnePipeline) {
  const Scene scene = load_scene(std::string(CIG_SOURCE_DIR) + "/scenes/airfield.json");
  const ImageGenerator pipeline(scene);
  const std::vector<int> channels{0, 1, 2};
  for (const char* engine : kPriorityEngines)
    for (int frame : {0, 9}) {
      const std::vector<ChannelOutput> one = pipeline.render(frame, channels, engine, {}, 1, 1);
      for (int n : {2, 4}) {
        const std::vector<ChannelOutput> many = pipeline.render(frame, channels, engine, {}, 1, n);
        for (std::size_t c = 0; c < channels.size(); ++c) {
          EXPECT_TRUE(one[c].out.image.rgb == many[c].out.image.rgb)
              << engine << " frame " << frame << " channel " << c << " pipelines " << n;
          EXPECT_TRUE(one[c].out.ids.id == many[c].out.ids.id)
              << engine << " frame " << frame << " channel " << c << " pipelines " << n;
          EXPECT_EQ(many[c].report["pipelines"]["polygons"].size(), std::size_t(n));
        }
      }
    }
}

// The formatter grid setting at eq. 1's own grid (subpixel=3 at 512 lines) renders the airfield bit
// for bit as without it, on one and on two pipelines: the fan split still decides on the positions
// as given (the polygons with non-planar I or 1/Z are many there), and the snap is the formatter's.
TEST(RenderingPipelines, AirfieldOnEq1GridSettingIsUnchanged) {
  const Scene scene = load_scene(std::string(CIG_SOURCE_DIR) + "/scenes/airfield.json");
  ASSERT_EQ(scene.raster, 512);
  const ImageGenerator pipeline(scene);
  EngineOptions on_grid;
  on_grid.params["subpixel"] = "3";
  // The segment engine on every channel, the quadtree's slower architecture model on one.
  const std::pair<const char*, std::vector<int>> runs[] = {{"segment", {0, 1, 2}}, {"quadtree", {1}}};
  for (const auto& [engine, channels] : runs)
    for (int n : {1, 2}) {
      const std::vector<ChannelOutput> plain = pipeline.render(0, channels, engine, {}, 1, n);
      const std::vector<ChannelOutput> set = pipeline.render(0, channels, engine, on_grid, 1, n);
      for (std::size_t c = 0; c < channels.size(); ++c) {
        EXPECT_TRUE(plain[c].out.image.rgb == set[c].out.image.rgb)
            << engine << " channel " << channels[c] << " n " << n;
        EXPECT_TRUE(plain[c].out.ids.id == set[c].out.ids.id) << engine << " channel " << channels[c] << " n " << n;
      }
    }
}

// The engine report without its wall times (the run's and the stages' ms; the modelled hardware
// times stay): what the workers must not change.
nlohmann::ordered_json counted(const nlohmann::ordered_json& report) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (auto it = report.begin(); it != report.end(); ++it) {
    const std::string& key = it.key();
    if (key == "ms" || key == "front_ms" || key == "segments_ms" || key == "video_ms") continue;
    out[key] = it->is_object() ? counted(*it) : *it;
  }
  return out;
}

// One image on 1..4 workers (render --threads with one channel): strips of the segment
// processor's video channel, the same bits and every count of the report (segments, overload,
// the cycle model) as one worker.
TEST(RenderingPipelines, StripsGiveTheSameImage) {
  const Scene scene = load_scene(std::string(CIG_SOURCE_DIR) + "/scenes/airfield.json");
  const ImageGenerator pipeline(scene);
  for (const char* engine : {"segment", "segment-double"}) {
    const std::vector<ChannelOutput> one = pipeline.render(3, {1}, engine, {}, 1);
    EXPECT_GT(one[0].report["raster"]["segments"]["polygon"].get<long>(), 0) << engine;
    for (int threads : {2, 3, 4}) {
      const std::vector<ChannelOutput> many = pipeline.render(3, {1}, engine, {}, threads);
      EXPECT_TRUE(one[0].out.image.rgb == many[0].out.image.rgb) << engine << " threads " << threads;
      EXPECT_TRUE(one[0].out.ids.id == many[0].out.ids.id) << engine << " threads " << threads;
      EXPECT_EQ(counted(one[0].report["raster"]), counted(many[0].report["raster"]))
          << engine << " threads " << threads;
    }
  }
}

}  // namespace
}  // namespace cig
