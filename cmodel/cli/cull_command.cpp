// cig cull SCENE [--frame K | --frames A:B] [--near D] [--far D] [--repeat R] [--report FILE]
// The study (cmodel/studies/culling_study.hpp) runs the methods; this prints its table and report.
#include "cli/cull_command.hpp"

#include <algorithm>
#include <iomanip>
#include <iostream>

#include "cli/output_plan.hpp"
#include "common/error.hpp"
#include "image/image.hpp"
#include "scene/scene_loader.hpp"
#include "studies/culling_study.hpp"

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

void print_table(const CullingStudy& s) {
  std::cout << "cig cull: " << s.objects << " objects, " << s.nodes << " quadtree nodes, " << s.channels
            << " channel image(s); per channel (mean):\n";
  std::cout << "method          nodes visited  nodes kept  objects kept  visible  time ms  false neg  false pos\n";
  for (const CullingRow& r : s.rows) {
    const double n = double(std::max(1L, s.channels));
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
  const CullingStudy study = run_culling_study(scene, {a, b, near_distance, far_distance, repeat});
  print_table(study);
  if (!report_file.empty()) {
    nlohmann::ordered_json rep = nlohmann::ordered_json::array();
    for (const CullingRow& r : study.rows)
      rep.push_back({{"method", cull_method_name(r.method)},
                     {"channels", study.channels},
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
