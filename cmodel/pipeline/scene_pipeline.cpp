#include "pipeline/scene_pipeline.hpp"

#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

#include "common/timing.hpp"
#include "geometry/geometric_processor.hpp"
#include "manager/scene_manager.hpp"
#include "registry/engine_registry.hpp"

namespace cig {

ScenePipeline::ScenePipeline(const Scene& scene, const CullSettings& culling)
    : scene_(scene), db_(build_world_database(scene)), tree_(std::make_unique<SceneQuadtree>(db_)) {
  manager_.tree = tree_.get();
  manager_.culling = culling;
}

ScreenFrame ScenePipeline::geometry(int frame, int channel, nlohmann::ordered_json& report) const {
  const auto t0 = Clock::now();
  const ChannelView view = make_channel_view(scene_, frame, channel);
  SceneManagerStats ms;
  PriorityList list = manage_channel(db_, view, ms, manager_);
  ms.ms = ms_since(t0);
  GeometryStats gs;
  ScreenFrame f = process_channel(scene_, db_, view, list, gs);
  nlohmann::ordered_json sizes = nlohmann::ordered_json::object();
  for (std::size_t k = 2; k < ms.group_sizes.size(); ++k)
    if (ms.group_sizes[k]) sizes[std::to_string(k)] = ms.group_sizes[k];
  report["scene_manager"] = {{"objects", ms.objects},
                             {"objects_visible", ms.objects_visible},
                             {"subobjects_tested", ms.subobjects_tested},
                             {"subobjects_visible", ms.subobjects_visible},
                             {"occlusion_groups",
                              {{"groups", ms.groups},
                               {"objects_in_groups_of_2_or_more", ms.grouped_objects},
                               {"largest", ms.largest_group},
                               {"groups_by_size", sizes},
                               {"sphere_pairs_tested", ms.pair_tests}}},
                             {"culling",
                              {{"method", cull_method_name(manager_.culling.method)},
                               {"tree_nodes", tree_->node_count()},
                               {"nodes_visited", ms.cull.nodes_visited},
                               {"nodes_kept", ms.cull.nodes_kept},
                               {"objects_kept", ms.cull.objects_kept},
                               {"tree_ms", ms.cull.ms},
                               {"sphere_tests_ms", ms.sphere_ms}}},
                             {"ms", ms.ms}};
  report["geometry"] = {{"polygons_in", gs.polygons_in},
                        {"backfacing", gs.backfacing},
                        {"outside", gs.outside},
                        {"clipped", gs.clipped},
                        {"degenerate", gs.degenerate},
                        {"polygons_out", gs.polygons_out},
                        {"vertices_out", gs.vertices_out},
                        {"light_points_in", gs.light_points_in},
                        {"light_points_out", gs.light_points_out},
                        {"ms", gs.ms}};
  return f;
}

std::vector<ChannelOutput> ScenePipeline::render(int frame, const std::vector<int>& channels, const std::string& engine,
                                                 const EngineOptions& options, int threads) const {
  std::vector<ChannelOutput> out(channels.size());
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  const int n = std::max(1, std::min<int>(threads, int(channels.size())));
  if (int(engines_.size()) < n) engines_.resize(std::size_t(n));
  std::string key = engine + (options.snap ? " snap" : "");
  for (const auto& [k, v] : options.params) key += " " + k + "=" + v;
  for (int i = 0; i < n; ++i) {
    EngineSlot& slot = engines_[std::size_t(i)];
    if (!slot.engine || slot.name != key) slot = {key, make_engine(engine, options)};
  }
  std::atomic<int> next_slot{0};
  auto worker = [&] {
    try {
      RasterEngine* eng = engines_[std::size_t(next_slot++)].engine.get();
      for (std::size_t k; (k = next++) < channels.size();) {
        ChannelOutput& co = out[k];
        co.channel = channels[k];
        co.report["channel"] = co.channel;
        co.report["name"] = scene_.channels[std::size_t(co.channel)].name;
        ScreenFrame f = geometry(frame, co.channel, co.report);
        const auto t0 = Clock::now();
        EngineRun run = eng->render(f);
        run.report["ms"] = ms_since(t0);
        co.out = std::move(run.out);
        co.report["raster"] = std::move(run.report);
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(error_mutex);
      if (!error) error = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (int i = 1; i < n; ++i) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  return out;
}

}  // namespace cig
