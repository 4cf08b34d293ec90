// `cig render` (render_command.cpp): frames of a scene through stages A, B and an engine, one PNG per
// channel, a panorama, and a report.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "cli/cli_common.hpp"

namespace cig::cli {

// What the priority compiler did, for a subobject or the whole scene (render and compare reports).
nlohmann::ordered_json priority_report(const PriorityCompileSummary& p);

struct RenderCommand {
  CLI::App* sub = nullptr;
  std::string scene_file, out_dir = "out", report_file, frames_text;
  int frame_k = -1, channel = -1, threads = 1;
  int pipelines = 1;     // rendering pipelines per channel (seed 000's Nc)
  double budget_ms = 0;  // --budget-ms: the frame governor (cli/governed_frames.hpp); 0 = off
  bool write_ids_files = false;
  bool html = false;  // --html: DIR/index.html
  CLI::Option* frame_opt = nullptr;
  EngineArgs engine;
  ModelLimitArgs model_limit;
  ManagerUnitArgs manager_unit;
  void add_to(CLI::App& app);
  int run();
};

}  // namespace cig::cli
