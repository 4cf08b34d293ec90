#include "cli/timing_command.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>

#include "cli/gnuplot_plot.hpp"
#include "cli/governed_frames.hpp"
#include "cli/output_plan.hpp"
#include "common/progress.hpp"
#include "generator/image_generator.hpp"
#include "image/image_compare.hpp"
#include "registry/engine_registry.hpp"
#include "scene/scene_loader.hpp"
#include "studies/frame_timing.hpp"

namespace cig::cli {

void TimingCommand::add_to(CLI::App& app) {
  threads = int(std::max(1u, std::thread::hardware_concurrency()));
  sub = app.add_subcommand("timing",
                           "the machine in time: per frame each stage's modelled ms (A, B, raster, video), the "
                           "limiting stage, frame time and transport delay; percentiles and frames over budget");
  sub->add_option("scene", scene_file, "scene file")->required();
  sub->add_option("--frames", frames_text, "inclusive frame range A:B (default: every frame)");
  sub->add_option("--channel", channel, "only this channel (default: all; a frame takes its slowest channel)")
      ->check(CLI::Range(0, kMaxChannelIndex));
  sub->add_option("--pipelines", pipelines, "rendering pipelines per channel (seed 000's Nc)")
      ->check(CLI::Range(1, 16));
  sub->add_option("--threads", threads, "worker threads (default: cores); the figures do not depend on it")
      ->check(CLI::Range(1, 64));
  sub->add_option("--budget-ms", budget_ms,
                  "the frame budget in ms (default 40: seed 001's two 20 ms fields); frames over it are counted")
      ->check(CLI::Range(0.1, 1e6));
  sub->add_option("--report", report_file, "write every frame's stages and the summary as JSON");
  sub->add_option("--plot", plot_file, "write a PNG: frame time and each stage over the frames, and the budget");
  sub->add_flag("--quiet", quiet, "print the summary only, not a line per frame");
  engine.add_to(sub, true);
  model_limit.add_to(sub);
  manager_unit.add_to(sub);
}

namespace {

void print_row(const FrameTiming& t) {
  const ChannelTiming* slowest = &t.channels.front();
  for (const ChannelTiming& c : t.channels)
    if (c.frame_ms > slowest->frame_ms) slowest = &c;
  const StageTimes& s = slowest->stages;
  std::cout << std::setw(6) << t.frame << std::setw(4) << slowest->channel << std::fixed << std::setprecision(3)
            << std::setw(9) << s.a_ms << std::setw(9) << s.b_ms << std::setw(10) << s.raster_ms << std::setw(9)
            << s.video_ms << "  " << std::left << std::setw(7) << t.limiting << std::right << std::setw(9) << t.frame_ms
            << std::setw(11) << t.transport_ms << std::setw(9) << t.underrun_lines << (t.over_budget ? "  over" : "")
            << "\n";
}

struct Summary {
  double p50 = 0, p99 = 0, max = 0, transport_p50 = 0, transport_max = 0;
  int over = 0, underrun_frames = 0;
  std::map<std::string, int> limiting;
  // Each unit's longest time over the frames and channels: what it must shed to fit the budget.
  double a_max = 0, geometry_max = 0, edges_max = 0, raster_max = 0, video_max = 0;
};

// The speed-up a unit needs to fit `budget` in every frame (1 when it fits). Each of these times is
// linear in its unit's speed: stage A and B count operations at a clock, the edge generator 10 us an
// edge, the raster engines' cycle models cycles at a clock or memory cycles (seed 001's 400 ns write).
double speedup(double ms, double budget) { return std::max(1.0, ms / budget); }

void print_to_fit(const Summary& s, double budget) {
  auto line = [&](const char* unit, double ms, const std::string& how) {
    std::cout << "  " << std::left << std::setw(24) << unit << std::right << std::fixed << std::setprecision(3)
              << std::setw(10) << ms << " ms  ";
    if (ms <= budget) std::cout << "fits\n";
    else std::cout << std::setprecision(2) << speedup(ms, budget) << "x faster: " << how << "\n";
  };
  const double b = speedup(s.geometry_max, budget), e = speedup(s.edges_max, budget);
  std::ostringstream geometry, edges;
  geometry << "clock 125 -> " << std::setprecision(0) << std::fixed << 125 / b << " ns, or " << int(std::ceil(b))
           << " processor pairs side by side";
  edges << std::setprecision(2) << std::fixed << 10 / e << " us an edge, or " << int(std::ceil(e))
        << " edge generators";
  std::cout << "to fit " << budget << " ms in every frame (each unit's longest time):\n";
  line("A scene manager", s.a_max,
       "a clock of " + std::to_string(int(std::ceil(100 * speedup(s.a_max, budget)))) + " MHz");
  line("B geometric processor", s.geometry_max, geometry.str());
  line("  edge generator", s.edges_max, edges.str());
  line("raster", s.raster_max, "its units or memory that much faster (docs/results/machine_timing.md)");
  line("video", s.video_max, "the video channel's read that much faster");
}

Summary summarise(const std::vector<FrameTiming>& rows) {
  Summary s;
  std::vector<double> ms, transport;
  for (const FrameTiming& t : rows) {
    ms.push_back(t.frame_ms);
    transport.push_back(t.transport_ms);
    s.over += t.over_budget ? 1 : 0;
    s.underrun_frames += t.underrun_lines > 0 ? 1 : 0;
    ++s.limiting[t.limiting];
    for (const ChannelTiming& c : t.channels) {
      s.a_max = std::max(s.a_max, c.stages.a_ms);
      s.geometry_max = std::max(s.geometry_max, c.geometry_ms);
      s.edges_max = std::max(s.edges_max, c.edge_generator_ms);
      s.raster_max = std::max(s.raster_max, c.stages.raster_ms);
      s.video_max = std::max(s.video_max, c.stages.video_ms);
    }
  }
  s.p50 = percentile(ms, 50);
  s.p99 = percentile(ms, 99);
  s.max = percentile(ms, 100);
  s.transport_p50 = percentile(transport, 50);
  s.transport_max = percentile(transport, 100);
  return s;
}

nlohmann::ordered_json summary_json(const Summary& s, double budget) {
  return {{"frame_ms", {{"p50", s.p50}, {"p99", s.p99}, {"max", s.max}}},
          {"transport_ms", {{"p50", s.transport_p50}, {"max", s.transport_max}}},
          {"limiting", s.limiting},
          {"unit_max_ms",
           {{"a", s.a_max},
            {"geometry", s.geometry_max},
            {"edge_generator", s.edges_max},
            {"raster", s.raster_max},
            {"video", s.video_max}}},
          {"speedup_to_fit",
           {{"a", speedup(s.a_max, budget)},
            {"geometry", speedup(s.geometry_max, budget)},
            {"edge_generator", speedup(s.edges_max, budget)},
            {"raster", speedup(s.raster_max, budget)},
            {"video", speedup(s.video_max, budget)}}},
          {"budget_ms", budget},
          {"frames_over_budget", s.over},
          {"frames_with_underruns", s.underrun_frames}};
}

void plot(const std::vector<FrameTiming>& rows, double budget, const std::string& file) {
  const GnuplotJob job("timing");
  const std::string data = job.file("frames.dat");
  {
    std::ofstream out(data);
    for (const FrameTiming& t : rows) {
      StageTimes worst;
      for (const ChannelTiming& c : t.channels) {
        worst.a_ms = std::max(worst.a_ms, c.stages.a_ms);
        worst.b_ms = std::max(worst.b_ms, c.stages.b_ms);
        worst.raster_ms = std::max(worst.raster_ms, c.stages.raster_ms);
        worst.video_ms = std::max(worst.video_ms, c.stages.video_ms);
      }
      out << t.frame << " " << t.frame_ms << " " << worst.a_ms << " " << worst.b_ms << " " << worst.raster_ms << " "
          << worst.video_ms << " " << t.transport_ms << "\n";
    }
  }
  const std::string d = "'" + data + "'";
  const std::string script =
      "set grid\nset key outside right\nset xlabel 'frame'\nset ylabel 'ms (model)'\n"
      "plot " +
      d + " using 1:2 with lines lw 2 title 'frame time', " + d + " using 1:3 with lines title 'A', " + d +
      " using 1:4 with lines title 'B', " + d + " using 1:5 with lines title 'raster', " + d +
      " using 1:6 with lines title 'video', " + d + " using 1:7 with lines dt 2 title 'transport delay', " +
      std::to_string(budget) + " with lines dt 3 lc rgb 'red' title 'budget'\n";
  job.draw(script, 1000, 500, file, "--plot");
}

void print_governed(const GovernedFrame& g) {
  std::cout << std::setw(6) << g.governed.frame << std::fixed << std::setprecision(3) << std::setw(11)
            << g.ungoverned.frame_ms << std::setw(10) << g.governed.frame_ms << std::setw(10) << g.predicted_ms
            << std::setprecision(1) << std::setw(8) << 100 * g.prediction_error << "%  " << std::left << std::setw(7)
            << g.governed.limiting << std::right << std::setprecision(0) << std::setw(8) << g.range << std::setw(7)
            << g.objects_cut << std::setw(8) << g.polygons_dropped << std::setprecision(2) << std::setw(8) << g.psnr
            << (g.governed.over_budget ? "  OVER" : "") << "\n";
}

}  // namespace

namespace {

void print_summary(const Summary& s, std::size_t frames, double budget, const char* label) {
  std::cout << std::fixed << std::setprecision(3) << label << "frame ms: p50 " << s.p50 << "  p99 " << s.p99 << "  max "
            << s.max << "; transport delay ms: p50 " << s.transport_p50 << "  max " << s.transport_max << "\n"
            << label << "limiting stage:";
  for (const auto& [stage, n] : s.limiting) std::cout << " " << stage << " " << n;
  std::cout << "\n"
            << label << "frames over budget: " << s.over << " of " << frames << " (budget " << budget
            << " ms; frames with video underruns " << s.underrun_frames << ")\n";
}

}  // namespace

int TimingCommand::run() {
  EngineOptions eo = engine.options();
  const Scene scene = load_scene(scene_file, model_limit.limits());
  int a = 0, b = scene.frame_count() - 1;
  if (!frames_text.empty()) frame_range(frames_text, -1, false, scene.frame_count(), scene_file, a, b);
  const std::vector<int> channels = selected_channels(scene, channel);
  probe_engine(engine.engine, eo, scene, pipelines);
  refuse_engine_budget(eo);
  OutputPlan plan;
  plan.scene_inputs(scene);
  plan.report_and_plot(report_file, plot_file);
  plan.check();

  MachineTimingParams p;
  const bool governed = budget_ms > 0;
  if (governed) p.budget_ms = budget_ms;
  std::unique_ptr<ImageGenerator> generator;
  std::unique_ptr<GovernedRun> run;  // --budget-ms: every frame without and with the governor
  if (governed) run = std::make_unique<GovernedRun>(scene, manager_unit.arith(), engine.engine, eo, budget_ms);
  else generator = std::make_unique<ImageGenerator>(scene, CullSettings{}, manager_unit.arith());
  std::vector<FrameTiming> rows, governed_rows;
  std::vector<GovernedFrame> governed_frames;
  Progress progress("cig timing", b - a + 1);
  if (!quiet)
    std::cout << (governed
                      ? " frame  ungoverned  governed  predicted   error  limits   range m    cut  dropped    PSNR\n"
                      : " frame  ch     A ms     B ms  raster ms  video ms  limits  frame ms  transport  underrun\n");
  for (int frame = a; frame <= b; ++frame) {
    std::vector<ChannelOutput> outs, gouts;
    if (governed) governed_frames.push_back(run->render(frame, channels, threads, pipelines, outs, gouts));
    else outs = generator->render(frame, channels, engine.engine, eo, threads, pipelines);
    for (const ChannelOutput& co : outs)
      if (!co.report["raster"].contains("hardware_ms"))
        throw InputError("", "--engine",
                         "engine '" + engine.engine +
                             "' has no hardware time model (timing takes the segment, quadtree and invparam engines)");
    if (governed) {
      rows.push_back(governed_frames.back().ungoverned);
      governed_rows.push_back(governed_frames.back().governed);
      if (!quiet) print_governed(governed_frames.back());
    } else {
      rows.push_back(frame_timing_of(frame, scene.raster, outs, p));
      if (!quiet) print_row(rows.back());
    }
    progress.step("frame " + std::to_string(frame));
  }
  const Summary s = summarise(rows);
  print_summary(s, rows.size(), p.budget_ms, governed ? "without the governor: " : "");
  print_to_fit(s, p.budget_ms);
  nlohmann::ordered_json rep = {{"command", "timing"},     {"scene", scene_file},
                                {"engine", engine.engine}, {"frames", {a, b}},
                                {"pipelines", pipelines},  {"summary", summary_json(s, p.budget_ms)}};
  if (governed) {
    const Summary g = summarise(governed_rows);
    print_summary(g, governed_rows.size(), p.budget_ms, "with the governor:    ");
    const nlohmann::ordered_json gs = governor_summary(governed_frames);
    std::cout << std::fixed << std::setprecision(1) << "prediction error: p50 "
              << 100 * gs["prediction_error_abs"]["p50"].get<double>() << "%  max "
              << 100 * gs["prediction_error_abs"]["max"].get<double>() << "%; image cost, PSNR against the "
              << "ungoverned frame: p50 " << std::setprecision(2) << gs["psnr_against_ungoverned"]["p50"].get<double>()
              << " dB  min " << gs["psnr_against_ungoverned"]["min"].get<double>() << " dB\n";
    rep["governed_summary"] = summary_json(g, p.budget_ms);
    rep["governor"] = gs;
  }
  if (!report_file.empty()) {
    rep["per_frame"] = nlohmann::ordered_json::array();
    for (std::size_t k = 0; k < rows.size(); ++k)
      rep["per_frame"].push_back(governed ? governed_json(governed_frames[k]) : frame_timing_json(rows[k]));
    write_text_file(report_file, report_text(rep));
  }
  if (!plot_file.empty()) plot(governed ? governed_rows : rows, p.budget_ms, plot_file);
  return 0;
}

}  // namespace cig::cli
