// cig cull SCENE [--frame K | --frames A:B] [--near D] [--far D] [--repeat R] [--report FILE]
#include "cli/cull_command.hpp"

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <limits>

#include "cli/output_plan.hpp"
#include "common/error.hpp"
#include "common/timing.hpp"
#include "image/image.hpp"
#include "manager/scene_manager.hpp"
#include "scene/scene_loader.hpp"

namespace cig::cli {

void CullCommand::add_to(CLI::App& app) {
  sub = app.add_subcommand("cull", "the scene quadtree's culling methods against brute force (seed 003's table)");
  sub->add_option("scene", scene_file, "scene file")->required();
  frame_opt = sub->add_option("--frame", frame_k, "frame number (default 0)");
  sub->add_option("--frames", frames_text, "inclusive frame range A:B")->excludes(frame_opt);
  sub->add_option("--near", near_distance, "D_near of the line-of-sight method, m (default 2000)")
      ->check(CLI::Range(0.0, 1e9));
  sub->add_option("--far", far_distance, "D_far of the line-of-sight method, m (default 8000)")
      ->check(CLI::Range(0.0, 1e9));
  sub->add_option("--repeat", repeat, "time each channel R times, keep the best (default 3)")
      ->check(CLI::Range(1, 1000));
  sub->add_option("--report", report_file, "write the table as JSON");
  model_limit.add_to(sub);
}

namespace {

struct CullRow {
  CullMethod method;
  std::uint64_t nodes_visited = 0, nodes_kept = 0, objects_kept = 0, visible = 0, false_negatives = 0,
                false_positives = 0;
  double ms = 0;  // sum over channels of the best time (tree walk and the kept objects' sphere tests)
};

// One method on one channel: the best of `repeat` runs, and its visible set.
std::vector<std::uint32_t> run_method(const WorldDatabase& db, const ChannelView& view, const ManagerOptions& options,
                                      int repeat, CullRow& row) {
  std::vector<std::uint32_t> ids;
  double best = std::numeric_limits<double>::infinity();
  SceneManagerStats kept;
  for (int r = 0; r < repeat; ++r) {
    SceneManagerStats st;
    const auto t0 = Clock::now();
    ids = potentially_visible(db, view, options, st);
    best = std::min(best, ms_since(t0));
    kept = st;
  }
  row.ms += best;
  row.nodes_visited += kept.cull.nodes_visited;
  row.nodes_kept += kept.cull.nodes_kept;
  row.objects_kept += options.tree ? kept.cull.objects_kept : db.objects.size();
  row.visible += ids.size();
  return ids;
}

void print_table(const std::vector<CullRow>& rows, long channels, std::size_t objects, std::size_t nodes) {
  std::cout << "cig cull: " << objects << " objects, " << nodes << " quadtree nodes, " << channels
            << " channel image(s); per channel (mean):\n";
  std::cout << "method          nodes visited  nodes kept  objects kept  visible  time ms  false neg  false pos\n";
  for (const CullRow& r : rows) {
    const double n = double(std::max(1L, channels));
    std::cout << std::left << std::setw(15) << cull_method_name(r.method) << std::right << std::fixed
              << std::setprecision(1) << std::setw(14) << r.nodes_visited / n << std::setw(12) << r.nodes_kept / n
              << std::setw(14) << r.objects_kept / n << std::setw(9) << r.visible / n << std::setprecision(4)
              << std::setw(9) << r.ms / n << std::setw(11) << r.false_negatives << std::setw(11) << r.false_positives
              << "\n";
  }
}

}  // namespace

int CullCommand::run() {
  const Scene scene = load_scene(scene_file, model_limit.limits());
  int a = 0, b = 0;
  frame_range(frames_text, frame_k, frame_opt->count() > 0, scene.frame_count(), scene_file, a, b);
  OutputPlan plan;
  plan.scene_inputs(scene);
  if (!report_file.empty()) plan.file(report_file, "--report");
  plan.check();
  if (!(near_distance <= far_distance)) throw InputError("", "--near", "D_near must not exceed D_far");
  const WorldDatabase db = build_world_database(scene);
  const SceneQuadtree tree(db);
  std::vector<CullRow> rows;
  for (CullMethod m :
       {CullMethod::kLineOfSight, CullMethod::kProjection, CullMethod::kHierarchical, CullMethod::kBruteForce})
    rows.push_back({m});
  long channels = 0;
  for (int frame = a; frame <= b; ++frame)
    for (int c = 0; c < int(scene.channels.size()); ++c, ++channels) {
      const ChannelView view = make_channel_view(scene, frame, c);
      std::vector<std::uint32_t> want;  // brute force (the last row) runs first: the others' truth
      for (std::size_t k = 0; k < rows.size(); ++k) {
        CullRow& row = rows[(k + rows.size() - 1) % rows.size()];
        ManagerOptions o;
        o.tree = row.method == CullMethod::kBruteForce ? nullptr : &tree;
        o.culling = {row.method, near_distance, far_distance};
        const std::vector<std::uint32_t> got = run_method(db, view, o, repeat, row);
        if (row.method == CullMethod::kBruteForce) want = got;
        std::vector<std::uint32_t> missing, extra;
        std::set_difference(want.begin(), want.end(), got.begin(), got.end(), std::back_inserter(missing));
        std::set_difference(got.begin(), got.end(), want.begin(), want.end(), std::back_inserter(extra));
        row.false_negatives += missing.size();
        row.false_positives += extra.size();
      }
    }
  print_table(rows, channels, db.objects.size(), tree.node_count());
  if (!report_file.empty()) {
    nlohmann::ordered_json rep = nlohmann::ordered_json::array();
    for (const CullRow& r : rows)
      rep.push_back({{"method", cull_method_name(r.method)},
                     {"channels", channels},
                     {"nodes_visited", r.nodes_visited},
                     {"nodes_kept", r.nodes_kept},
                     {"objects_kept", r.objects_kept},
                     {"visible", r.visible},
                     {"ms", r.ms},
                     {"false_negatives", r.false_negatives},
                     {"false_positives", r.false_positives}});
    write_text_file(report_file, report_text(rep));
  }
  return 0;
}

}  // namespace cig::cli
