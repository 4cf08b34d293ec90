// cig cosim SCENE|POLYS [--processor quadtree] [--arch STR] [--frame K | --frames A:B] [--channel C]
//                       [--fan-split on|off] [--trace FILE.fst [--trace-cycles A:B] [--trace-depth N]]
//                       [--stall-seed S] [--input-gaps P] [--output-stalls P] [--start-window screen|bbox]
//                       [--report FILE]
// cig cosim SCENE --processor invparam [--bits W] [--pps N] [--frame K | --frames A:B] [--channel C]
//                       [--trace FILE.fst [--trace-cycles A:B] [--trace-depth N]] [--stall-seed S]
//                       [--input-gaps P] [--vt-stalls P] [--report FILE]
// The options of both processors and the checks they share; each processor's run is in its folder
// (quadtree/cosim_quadtree.cpp, invparam/cosim_invparam.cpp).
#include "cosim_command.hpp"

#include <iostream>

#include "cli/cli_common.hpp"
#include "cli/frame_jobs.hpp"
#include "cli/output_plan.hpp"
#include "common/error.hpp"
#include "cosim_trace.hpp"

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
  app.add_option("--trace", trace_file,
                 "write the RTL's waveform (FST) of the first image, one clock period a cycle, and FILE.gtkw "
                 "(gtkwave's save file: the signals grouped)");
  trace_cycles_opt =
      app.add_option("--trace-cycles", trace_cycles,
                     "with --trace: only cycles A..B (inclusive) of the traced image (a full image can take GBs)");
  trace_depth_opt = app.add_option("--trace-depth", trace_depth,
                                   "with --trace: only signals down to N scope levels below the top (1: its ports)")
                        ->check(CLI::Range(1, 64));
  quadtree_only.push_back(app.add_option("--fan-split", fan_split,
                                         "split polygons whose vertex I or 1/Z are not planar into triangle fans: on "
                                         "(default, the stream of every quadtree engine command) | off")
                              ->check(CLI::IsMember({"on", "off"})));
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
  invparam_only.push_back(app.add_option(
      "--bits", word_bits,
      "invparam: the seed's word length W (hls Word<W>; the RTL's registers have W + 16 bits; default 64)"));
  invparam_only.push_back(app.add_option(
      "--pps", pps, "invparam: pixel processors N_PP (default 64): frames set up on an N_PP x N_PP lattice"));
  app.add_option("--report", report_file, "write a JSON report");
  model_limit.add_to(&app);
}

int CosimCommand::run() {
  const bool ip = parse_processor(processor) == HardwareProcessor::kInvparam;
  for (const CLI::Option* o : ip ? quadtree_only : invparam_only)
    if (o->count() > 0)
      throw InputError("", o->get_name(),
                       std::string("only with --processor ") +
                           processor_name(ip ? HardwareProcessor::kQuadtree : HardwareProcessor::kInvparam));
  return ip ? run_invparam() : run_quadtree();
}

void CosimCommand::check_outputs(const FrameJobs& jobs, const CosimTrace& trace) const {
  OutputPlan plan;
  jobs.declare_inputs(plan);
  if (!report_file.empty()) plan.file(report_file, "--report");
  trace.declare_outputs(plan);
  plan.check();
}

void CosimTotals::add(long long n_compared, long long n_mismatches, bool cycles_equal,
                      const std::string& first_mismatch) {
  compared += n_compared;
  mismatches += n_mismatches;
  bad_cycles += cycles_equal ? 0 : 1;
  if (first.empty()) first = first_mismatch;
}

int CosimTotals::finish(nlohmann::ordered_json& rep, const char* what, const char* compared_key,
                        const char* images) const {
  std::cout << "all: " << compared << " " << what << " compared, " << mismatches << " mismatches, " << bad_cycles << " "
            << images << " with a cycle mismatch\n";
  if (!first.empty()) std::cout << "first mismatch: " << first << "\n";
  rep[compared_key] = compared;
  rep["mismatches"] = mismatches;
  rep["cycle_mismatches"] = bad_cycles;
  return mismatches == 0 && bad_cycles == 0 ? 0 : 1;
}

}  // namespace cig::cli
