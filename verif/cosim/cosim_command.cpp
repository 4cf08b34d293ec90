// cig cosim SCENE|POLYS [--processor quadtree] [--arch STR] [--frame K | --frames A:B] [--channel C]
//                       [--trace FILE.fst] [--stall-seed S] [--input-gaps P] [--output-stalls P]
//                       [--start-window screen|bbox] [--report FILE]
// cig cosim SCENE --processor invparam [--bits W] [--pps N] [--frame K | --frames A:B] [--channel C]
//                       [--trace FILE.fst] [--stall-seed S] [--input-gaps P] [--vt-stalls P] [--report FILE]
#include <filesystem>
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/cli_common.hpp"
#include "cli/frame_jobs.hpp"
#include "cli/output_plan.hpp"
#include "common/error.hpp"
#include "cosim.hpp"
#include "cosim_command.hpp"
#include "hls/formatter/sample_lattice.hpp"

namespace cig::cli {

void CosimCommand::add_options(CLI::App& app) {
  app.add_option("input", input, "scene or polygon list")->required();
  app.add_option("--processor", processor,
                 "quadtree (default: the raster processor, seed 004) or invparam (the inverse-parameter array, "
                 "seed 002: a scene's polyhedra)")
      ->check(CLI::IsMember({"quadtree", "invparam"}));
  quadtree_only.push_back(app.add_option(
      "--arch", arch, "architecture: one the RTL build has (np or kp(n-k)t with a 2-level tree); default np"));
  frame_opt = app.add_option("--frame", frame_k, "frame number (scenes; default 0)");
  app.add_option("--frames", frames_text, "inclusive frame range A:B (scenes)")->excludes(frame_opt);
  app.add_option("--channel", channel, "only this channel (scenes)")->check(CLI::Range(0, kMaxChannelIndex));
  app.add_option("--trace", trace_file, "write the RTL's waveform (FST) of the first image");
  app.add_option("--stall-seed", stall_seed, "seed of the verification stall pattern (default 1)");
  app.add_option("--input-gaps", input_gaps, "percent of cycles the input port offers nothing (0..95; invparam 0..75)")
      ->check(CLI::Range(0, 95));
  quadtree_only.push_back(
      app.add_option("--output-stalls", output_stalls, "percent of cycles the pixel processors take nothing (0..95)")
          ->check(CLI::Range(0, 95)));
  quadtree_only.push_back(
      app.add_option("--start-window", start_window,
                     "where a polygon's subdivision starts: screen (default, the seed) or bbox (its start window)")
          ->check(CLI::IsMember({"screen", "bbox"})));
  invparam_only.push_back(
      app.add_option("--vt-stalls", vt_stalls, "invparam: percent of cycles the VT consumer takes nothing (0..75)")
          ->check(CLI::Range(0, 75)));
  invparam_only.push_back(app.add_option("--bits", word_bits, "invparam: the word length W of the RTL (default 64)"));
  invparam_only.push_back(app.add_option(
      "--pps", pps, "invparam: pixel processors N_PP (default 64): frames set up on an N_PP x N_PP lattice"));
  app.add_option("--report", report_file, "write a JSON report");
  model_limit.add_to(&app);
}

int CosimCommand::run() {
  const bool ip = processor == "invparam";
  for (const CLI::Option* o : ip ? quadtree_only : invparam_only)
    if (o->count() > 0)
      throw InputError("", o->get_name(), std::string("only with --processor ") + (ip ? "quadtree" : "invparam"));
  return ip ? run_invparam() : run_quadtree();
}

int CosimCommand::run_quadtree() {
  const FrameJobs jobs =
      FrameJobs::load(input, frames_text, frame_k, frame_opt->count() > 0, channel, model_limit.limits());
  const int raster = jobs.screen_frame(0).raster;
  const int log2 = hls::raster_log2_of(raster);
  std::string wanted = arch.empty() ? std::to_string(log2) + "p" : arch;
  const quad::Architecture a = quad::Architecture::parse(wanted, log2, "--arch");
  cosim::RtlConfig cfg{0, 0};
  std::string have;
  for (const cosim::RtlConfig& c : cosim::rtl_configs()) {
    if (c.raster_log2 == log2) have += (have.empty() ? "" : ", ") + c.arch_text();
    if (c.raster_log2 == log2 && c.arch_text() == a.text) cfg = c;
  }
  if (cfg.raster_log2 == 0)
    throw InputError("", "--arch",
                     "the RTL build has no configuration " + a.text + " for a " + std::to_string(raster) +
                         "-line raster" +
                         (have.empty() ? " (it has none for that raster)" : " (it has: " + have + ")"));
  OutputPlan plan;
  jobs.declare_inputs(plan);
  if (!report_file.empty()) plan.file(report_file, "--report");
  if (!trace_file.empty()) plan.file(trace_file, "--trace");
  plan.check();
  auto rtl = cosim::make_rtl_runner(cfg.raster_log2, cfg.tree_levels);
  if (!trace_file.empty()) {
    const auto parent = std::filesystem::path(trace_file).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    rtl->trace_to(trace_file);
  }
  const cosim::StallConfig stalls{stall_seed, input_gaps, output_stalls, start_window == "bbox"};
  std::cout << "cig cosim: " << input << ", architecture " << a.text << " (" << a.pe_count()
            << " PEs), stalls: input gaps " << input_gaps << " %, output stalls " << output_stalls << " % (seed "
            << stall_seed << "), start window " << start_window << "\n";
  std::cout << " frame  ch   records  mismatch  cycles model  cycles RTL   equal  RTL cycles/s  model cycles/s\n";
  nlohmann::ordered_json rep;
  rep["command"] = "cosim";
  rep["input"] = input;
  rep["architecture"] = a.text;
  rep["start_window"] = start_window;
  rep["runs"] = nlohmann::ordered_json::array();
  long long records = 0, mismatches = 0, bad_cycles = 0;
  std::string first;
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    cosim::CosimResult r;
    try {
      r = cosim::cosim_frame(jobs.screen_frame(k), *rtl, cfg, stalls);
    } catch (const InputError& e) {
      // An input error leaves no output behind: the trace started for this run goes.
      if (!trace_file.empty()) {
        rtl.reset();
        std::filesystem::remove(trace_file);
      }
      if (!e.file().empty() || e.where() == "--arch") throw;
      throw InputError(
          input,
          "frame " + std::to_string(jobs.frame(k)) + " channel " + std::to_string(jobs.channel(k)) + ", " + e.where(),
          e.rule());
    }
    const double rtl_speed = r.rtl.seconds > 0 ? double(r.rtl.cycles) / r.rtl.seconds : 0;
    const double model_speed = r.model.seconds > 0 ? double(r.model.cycles) / r.model.seconds : 0;
    std::cout << std::setw(6) << jobs.frame(k) << std::setw(4) << jobs.channel(k) << std::setw(10)
              << r.comparison.records_compared << std::setw(10) << r.comparison.mismatches << std::setw(14)
              << r.model.cycles << std::setw(12) << r.rtl.cycles << std::setw(8)
              << (r.comparison.cycles_equal ? "yes" : "NO") << std::setw(14) << std::llround(rtl_speed) << std::setw(16)
              << std::llround(model_speed) << "\n";
    records += r.comparison.records_compared;
    mismatches += r.comparison.mismatches;
    bad_cycles += r.comparison.cycles_equal ? 0 : 1;
    if (first.empty() && !r.comparison.first.empty()) first = r.comparison.first;
    rep["runs"].push_back({{"frame", jobs.frame(k)},
                           {"channel", jobs.channel(k)},
                           {"records_compared", r.comparison.records_compared},
                           {"mismatches", r.comparison.mismatches},
                           {"cycles_model", r.model.cycles},
                           {"cycles_rtl", r.rtl.cycles},
                           {"rtl_cycles_per_second", rtl_speed},
                           {"model_cycles_per_second", model_speed},
                           {"first_mismatch", r.comparison.first}});
  }
  std::cout << "all: " << records << " records compared, " << mismatches << " mismatches, " << bad_cycles
            << " image(s) with a cycle mismatch\n";
  if (!first.empty()) std::cout << "first mismatch: " << first << "\n";
  rep["records_compared"] = records;
  rep["mismatches"] = mismatches;
  rep["cycle_mismatches"] = bad_cycles;
  if (!report_file.empty()) write_text_file(report_file, report_text(rep));
  return mismatches == 0 && bad_cycles == 0 ? 0 : 1;
}

}  // namespace cig::cli
