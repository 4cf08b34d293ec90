#include "generator/image_generator.hpp"

#include "common/parallel.hpp"
#include "common/timing.hpp"
#include "geometry/geometric_processor.hpp"
#include "manager/pipeline_loading.hpp"
#include "manager/scene_manager.hpp"
#include "registry/engine_registry.hpp"
#include "timing/geometry_timing.hpp"

namespace cig {

ImageGenerator::ImageGenerator(const Scene& scene, const CullSettings& culling, VisibilityArith visibility)
    : scene_(scene), db_(build_world_database(scene)), tree_(std::make_unique<SceneQuadtree>(db_)) {
  manager_.tree = tree_.get();
  manager_.culling = culling;
  manager_.visibility = visibility;
}

namespace {

nlohmann::ordered_json manager_report(const SceneManagerStats& ms, const ManagerOptions& manager,
                                      const SceneQuadtree& tree) {
  nlohmann::ordered_json sizes = nlohmann::ordered_json::object();
  for (std::size_t k = 2; k < ms.group_sizes.size(); ++k)
    if (ms.group_sizes[k]) sizes[std::to_string(k)] = ms.group_sizes[k];
  return {{"objects", ms.objects},
          {"objects_visible", ms.objects_visible},
          {"subobjects_tested", ms.subobjects_tested},
          {"subobjects_visible", ms.subobjects_visible},
          {"visibility_unit",
           {{"arithmetic", visibility_arith_name(manager.visibility)},
            {"spheres", ms.unit.spheres},
            {"spheres_out_of_format", ms.unit.spheres_out_of_format}}},
          {"occlusion_groups",
           {{"groups", ms.groups},
            {"objects_in_groups_of_2_or_more", ms.grouped_objects},
            {"largest", ms.largest_group},
            {"groups_by_size", sizes},
            {"sphere_pairs_tested", ms.pair_tests}}},
          {"culling",
           {{"method", cull_method_name(manager.culling.method)},
            {"tree_nodes", tree.node_count()},
            {"nodes_visited", ms.cull.nodes_visited},
            {"nodes_kept", ms.cull.nodes_kept},
            {"objects_kept", ms.cull.objects_kept},
            {"tree_ms", ms.cull.ms},
            {"sphere_tests_ms", ms.sphere_ms}}},
          {"ms", ms.ms}};
}

nlohmann::ordered_json operations_json(const OperationCounts& c) {
  return {{"R", c.R}, {"C", c.C}, {"O", c.O}, {"L", c.L}, {"A", c.A}, {"M", c.M}, {"D", c.D}};
}

// Stage B in time (timing/geometry_timing.hpp): the two processors' operations and modelled ms.
nlohmann::ordered_json geometry_timing_report(const GeometryStats& gs) {
  const GeometryTiming t = time_geometry(gs.transform_ops, gs.clip_ops, gs.vertices_transformed);
  return {{"vertices_transformed", gs.vertices_transformed},
          {"clip_intersections", gs.clip_intersections},
          {"divisions", gs.divisions},
          {"transform_operations", operations_json(gs.transform_ops)},
          {"clip_operations", operations_json(gs.clip_ops)},
          {"transform_ms", t.transform_ns * 1e-6},
          {"clip_ms", t.clip_ns * 1e-6},
          {"ms", t.frame_ns * 1e-6},
          {"limiting", t.limiting},
          {"vertices_per_second", t.vertices_per_second}};
}

nlohmann::ordered_json geometry_report(const GeometryStats& gs) {
  return {{"polygons_in", gs.polygons_in},
          {"backfacing", gs.backfacing},
          {"outside", gs.outside},
          {"clipped", gs.clipped},
          {"degenerate", gs.degenerate},
          {"polygons_out", gs.polygons_out},
          {"vertices_out", gs.vertices_out},
          {"light_points_in", gs.light_points_in},
          {"light_points_out", gs.light_points_out},
          {"light_points_outside_beam", gs.light_points_outside_beam},
          {"priority_trees",
           {{"subobjects", gs.bsp_subobjects},
            {"nodes_visited", gs.bsp.nodes},
            {"partition_tests", gs.bsp.partitions},
            {"operations", {{"L", gs.bsp.ops.L}, {"C", gs.bsp.ops.C}, {"A", gs.bsp.ops.A}, {"M", gs.bsp.ops.M}}}}},
          {"timing", geometry_timing_report(gs)},
          {"ms", gs.ms}};
}

}  // namespace

PriorityList ImageGenerator::manage(const ChannelView& view, nlohmann::ordered_json& report) const {
  const auto t0 = Clock::now();
  SceneManagerStats ms;
  PriorityList list = manage_channel(db_, view, ms, manager_);
  ms.ms = ms_since(t0);
  report["scene_manager"] = manager_report(ms, manager_, *tree_);
  return list;
}

PriorityList ImageGenerator::manage_governed(ChannelView& view, const FrameGovernor* governor,
                                             nlohmann::ordered_json& report) const {
  if (!governor) return manage(view, report);
  // The governor's own manager runs give the list and its figures (ms: stage A's runs, the
  // governor's bisection included).
  const auto t0 = Clock::now();
  GovernorDecision d;
  SceneManagerStats ms;
  PriorityList list = governor->choose(
      view.channel, view,
      [&](const ChannelView& v, SceneManagerStats& s) { return manage_channel(db_, v, s, manager_); }, db_, d, &ms);
  ms.ms = ms_since(t0);
  view.range = d.range;
  report["scene_manager"] = manager_report(ms, manager_, *tree_);
  report["governor"] = FrameGovernor::report(d);
  return list;
}

ScreenFrame ImageGenerator::geometry(int frame, int channel, nlohmann::ordered_json& report,
                                     const FrameGovernor* governor) const {
  ChannelView view = make_channel_view(scene_, frame, channel);
  const PriorityList list = manage_governed(view, governor, report);
  GeometryStats gs;
  ScreenFrame f = process_channel(scene_, db_, view, list, gs);
  report["geometry"] = geometry_report(gs);
  return f;
}

std::vector<ScreenFrame> ImageGenerator::geometry_parts(int frame, int channel, int pipelines,
                                                        nlohmann::ordered_json& report,
                                                        const FrameGovernor* governor) const {
  if (pipelines <= 1) return {geometry(frame, channel, report, governor)};
  ChannelView view = make_channel_view(scene_, frame, channel);
  const PipelineLoad load = load_pipelines(manage_governed(view, governor, report), db_, pipelines);
  GeometryStats gs;
  std::vector<ScreenFrame> parts;
  std::vector<std::uint64_t> polygons;
  for (const PriorityList& list : load.lists) {
    parts.push_back(process_channel(scene_, db_, view, list, gs));
    polygons.push_back(parts.back().polygons.size());
  }
  report["geometry"] = geometry_report(gs);
  report["pipelines"] = {{"count", pipelines},
                         {"polygons", polygons},
                         {"load_balance", load_balance(polygons)},
                         {"database_polygons", load.polygons},
                         {"cuts_inside_groups", load.cuts_inside_groups}};
  return parts;
}

std::vector<ChannelOutput> ImageGenerator::render(int frame, const std::vector<int>& channels,
                                                  const std::string& engine, const EngineOptions& options, int threads,
                                                  int pipelines, const FrameGovernor* governor) const {
  std::vector<ChannelOutput> out(channels.size());
  const int n = std::max(1, std::min<int>(threads, int(channels.size())));
  if (int(engines_.size()) < n) engines_.resize(std::size_t(n));
  // Threads left over by the channels split each image (strips, where the engine does).
  EngineOptions per_engine = options;
  per_engine.threads = std::max(1, threads / n);
  std::string key = engine + (options.snap ? " snap" : "") + " threads=" + std::to_string(per_engine.threads);
  for (const auto& [k, v] : options.params) key += " " + k + "=" + v;
  for (int i = 0; i < n; ++i) {
    EngineSlot& slot = engines_[std::size_t(i)];
    if (!slot.engine || slot.name != key) slot = {key, make_engine(engine, per_engine)};
  }
  parallel_for(channels.size(), n, [&](std::size_t k, int self) {
    RasterEngine* eng = engines_[std::size_t(self)].engine.get();
    ChannelOutput& co = out[k];
    co.channel = channels[k];
    co.report["channel"] = co.channel;
    co.report["name"] = scene_.channels[std::size_t(co.channel)].name;
    EngineRun run;
    if (pipelines > 1) {
      const std::vector<ScreenFrame> parts = geometry_parts(frame, co.channel, pipelines, co.report, governor);
      const auto t0 = Clock::now();
      run = eng->render_parts(parts);
      run.report["ms"] = ms_since(t0);
    } else {
      const ScreenFrame f = geometry(frame, co.channel, co.report, governor);
      const auto t0 = Clock::now();
      run = eng->render(f);
      run.report["ms"] = ms_since(t0);
    }
    co.out = std::move(run.out);
    co.report["raster"] = std::move(run.report);
  });
  return out;
}

}  // namespace cig
