// cig cosim [--processor quadtree] (the default; the options: ../cosim_command.cpp): the stream the
// quadtree engine runs (its fan split included) through the Verilated qt_raster and through the
// kernels + architecture model in lock step (cosim.hpp); per image the records compared, the
// mismatches, the cycles of both and the simulation speed.
#include <cmath>
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/cli_common.hpp"
#include "cli/frame_jobs.hpp"
#include "common/error.hpp"
#include "common/progress.hpp"
#include "cosim.hpp"
#include "cosim_command.hpp"
#include "cosim_trace.hpp"
#include "hls/formatter/sample_lattice.hpp"
#include "quadtree/quadtree_engine.hpp"

namespace cig::cli {
namespace {

// The configuration of the RTL build for the raster and --arch (InputError when there is none).
cosim::RtlConfig rtl_config(int raster, const std::string& arch, quad::Architecture& a) {
  const int log2 = hls::raster_log2_of(raster);
  a = quad::Architecture::parse(arch.empty() ? std::to_string(log2) + "p" : arch, log2, "--arch");
  std::string have;
  for (const cosim::RtlConfig& c : cosim::rtl_configs()) {
    if (c.raster_log2 == log2) have += (have.empty() ? "" : ", ") + c.arch_text();
    if (c.raster_log2 == log2 && c.arch_text() == a.text) return c;
  }
  throw InputError("", "--arch",
                   "the RTL build has no configuration " + a.text + " for a " + std::to_string(raster) +
                       "-line raster" + (have.empty() ? " (it has none for that raster)" : " (it has: " + have + ")"));
}

std::string image_name(const FrameJobs& jobs, std::size_t k) {
  return "frame " + std::to_string(jobs.frame(k)) + " channel " + std::to_string(jobs.channel(k));
}

// An input error of image k, named (errors of an option pass as they are).
[[noreturn]] void rethrow_for_image(const InputError& e, const std::string& input, const FrameJobs& jobs,
                                    std::size_t k) {
  if (!e.file().empty() || e.where().rfind("--", 0) == 0) throw e;
  throw InputError(input, image_name(jobs, k) + ", " + e.where(), e.rule());
}

// With --trace, for image 0: once its model has counted the image's cycles, the window checked
// against them and the trace begun (the RTL's run that follows); nothing without --trace.
cosim::BeforeRtl trace_start(CosimTrace& trace, const std::string& image, const cosim::RtlConfig& cfg,
                             cosim::RtlRunner& rtl) {
  if (!trace.on()) return {};
  return [&trace, image, &cfg, &rtl](long long cycles) {
    rtl.trace_to(trace.plan(0, cycles, std::llround(kQuadDefaultClockNs * 1e3), trace_cost(cfg.arch_text()), image));
  };
}

// Image k's line of the table (stdout) and its entry in the report.
nlohmann::ordered_json image_row(const FrameJobs& jobs, std::size_t k, const cosim::EngineStream& stream,
                                 const cosim::CosimResult& r) {
  const double rtl_speed = r.rtl.seconds > 0 ? double(r.rtl.cycles) / r.rtl.seconds : 0;
  const double model_speed = r.model.seconds > 0 ? double(r.model.cycles) / r.model.seconds : 0;
  std::cout << std::setw(6) << jobs.frame(k) << std::setw(4) << jobs.channel(k) << std::setw(10)
            << r.comparison.records_compared << std::setw(10) << r.comparison.mismatches << std::setw(14)
            << r.model.cycles << std::setw(12) << r.rtl.cycles << std::setw(8)
            << (r.comparison.cycles_equal ? "yes" : "NO") << std::setw(14) << std::llround(rtl_speed) << std::setw(16)
            << std::llround(model_speed) << std::setw(7) << stream.polygons_split << std::setw(7)
            << stream.triangles_added << "\n";
  return {{"frame", jobs.frame(k)},
          {"channel", jobs.channel(k)},
          {"stream",
           {{"fan_split", stream.fan_split},
            {"polygons", stream.frame.polygons.size()},
            {"polygons_split", stream.polygons_split},
            {"triangles_added", stream.triangles_added}}},
          {"records_compared", r.comparison.records_compared},
          {"mismatches", r.comparison.mismatches},
          {"cycles_model", r.model.cycles},
          {"cycles_rtl", r.rtl.cycles},
          {"rtl_cycles_per_second", rtl_speed},
          {"model_cycles_per_second", model_speed},
          {"first_mismatch", r.comparison.first}};
}

}  // namespace

int CosimCommand::run_quadtree() {
  CosimTrace trace(trace_file, trace_cycles, trace_depth, trace_cycles_opt->count() > 0, trace_depth_opt->count() > 0);
  const FrameJobs jobs =
      FrameJobs::load(input, frames_text, frame_k, frame_opt->count() > 0, channel, model_limit.limits());
  quad::Architecture a;
  const cosim::RtlConfig cfg = rtl_config(jobs.screen_frame(0).raster, arch, a);
  const cosim::StallConfig stalls{stall_seed, input_gaps, output_stalls, start_window == "bbox"};
  const std::unique_ptr<RasterEngine> engine = cosim::quadtree_engine(cfg, stalls, fan_split == "on");
  jobs.check_capacity(*engine);
  check_outputs(jobs, trace);
  auto rtl = cosim::make_rtl_runner(cfg.raster_log2, cfg.tree_levels);
  std::cout << "cig cosim: " << input << ", architecture " << a.text << " (" << a.pe_count()
            << " PEs), stalls: input gaps " << input_gaps << " %, output stalls " << output_stalls << " % (seed "
            << stall_seed << "), start window " << start_window << ", fan split " << fan_split
            << " (the stream of cig render/raster --engine quadtree)\n";
  std::cout << " frame  ch   records  mismatch  cycles model  cycles RTL   equal  RTL cycles/s  model cycles/s"
               "  split  +tris\n";
  nlohmann::ordered_json rep;
  rep["command"] = "cosim";
  rep["input"] = input;
  rep["architecture"] = a.text;
  rep["start_window"] = start_window;
  rep["fan_split"] = fan_split == "on";
  rep["runs"] = nlohmann::ordered_json::array();
  CosimTotals totals;
  Progress progress("cig cosim", (long long)jobs.size());
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    cosim::EngineStream stream;
    cosim::CosimResult r;
    try {
      stream = cosim::engine_stream(*engine, jobs.screen_frame(k));
      r = cosim::cosim_frame(
          stream.frame, *rtl, cfg, stalls, 200000000,
          [&](long long done, long long total) { progress.within(done, total, "RTL cycles"); },
          k == 0 ? trace_start(trace, image_name(jobs, k), cfg, *rtl) : cosim::BeforeRtl{});
    } catch (const InputError& e) {
      // An input error leaves no output behind: the trace started for this run goes.
      rtl.reset();
      trace.discard();
      rethrow_for_image(e, input, jobs, k);
    }
    rep["runs"].push_back(image_row(jobs, k, stream, r));
    totals.add(r.comparison.records_compared, r.comparison.mismatches, r.comparison.cycles_equal, r.comparison.first);
    if (k == 0 && trace.on())
      rep["trace"] = trace.finish(cosim::TracedDesign::kQuadtreeRaster, r.model.seconds + r.rtl.seconds);
    progress.step(image_name(jobs, k) + ": " + std::to_string(r.rtl.cycles) + " cycles");
  }
  const int status = totals.finish(rep, "records", "records_compared", "image(s)");
  if (!report_file.empty()) write_text_file(report_file, report_text(rep));
  return status;
}

}  // namespace cig::cli
