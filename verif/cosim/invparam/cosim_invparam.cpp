// cig cosim --processor invparam: a scene's frames (stage B's polyhedra, each set up on an
// N_PP x N_PP lattice) through the Verilated ip_array and the clock-level model, back to back
// without reset (ip_cosim.hpp; each frame's setup gives RGeps and RGnear, the scene's near plane,
// written between frames when they change); per frame the faces, samples, tokens, codes, the
// cycles of both, the held cycles and the mismatches. --bits is the seed's word W (hls Word<W>):
// the RTL's registers have W + 16 bits.
#include <cmath>
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/cli_common.hpp"
#include "cli/frame_jobs.hpp"
#include "common/error.hpp"
#include "common/progress.hpp"
#include "cosim_command.hpp"
#include "cosim_trace.hpp"
#include "invparam/invparam_engine.hpp"
#include "ip_cosim.hpp"

namespace cig::cli {
namespace {

// The frames before any output: each within the kernel's capacities, from a scene with polyhedra
// (a frame whose channel sees none is an empty frame) or with nothing at all.
std::vector<ScreenFrame> invparam_frames(const FrameJobs& jobs, const std::string& input) {
  std::vector<ScreenFrame> frames;
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    ScreenFrame f = jobs.screen_frame(k);
    const std::string where = "frame " + std::to_string(jobs.frame(k)) + " channel " + std::to_string(jobs.channel(k));
    if (f.polyhedra.empty() && !f.lists_polyhedra && !f.polygons.empty())
      throw InputError(input, where,
                       "--processor invparam draws convex polyhedra (scene objects with \"polyhedron\": true); this "
                       "image has " +
                           std::to_string(f.polygons.size()) + " polygon(s) and no polyhedron");
    try {
      invparam_face_list(f);
    } catch (const InputError& e) { throw InputError(input, where + ", " + e.where(), e.rule()); }
    frames.push_back(std::move(f));
  }
  return frames;
}

cosim::IpRtlConfig pick_config(int bits, int pps) {
  std::string have;
  for (const cosim::IpRtlConfig& c : cosim::ip_rtl_configs()) {
    if (c.w == bits && c.n_pp == pps) return c;
    have += (have.empty() ? "" : "; ") + c.text();
  }
  throw InputError("", "--bits/--pps",
                   "the RTL build has no ip_array configuration W=" + std::to_string(bits) +
                       ", N_PP=" + std::to_string(pps) + " (it has: " + have + ")");
}

std::string image_name(const FrameJobs& jobs, std::size_t k) {
  return "frame " + std::to_string(jobs.frame(k)) + " channel " + std::to_string(jobs.channel(k));
}

// Frame k's line of the table (stdout) and its entry in the report.
nlohmann::ordered_json frame_row(const FrameJobs& jobs, std::size_t k, const cosim::IpFrameResult& r) {
  const double speed = r.seconds > 0 ? double(r.rtl_cycles) / r.seconds : 0;
  std::cout << std::setw(6) << jobs.frame(k) << std::setw(4) << jobs.channel(k) << std::setw(7) << r.faces
            << std::setw(9) << r.samples << std::setw(8) << r.tokens << std::setw(8) << r.codes << std::setw(12)
            << r.rtl_cycles << std::setw(14) << r.model_cycles << std::setw(8) << r.held_cycles << std::setw(12)
            << r.mismatches << std::setw(14) << std::llround(speed) << "\n";
  return {{"frame", jobs.frame(k)},
          {"channel", jobs.channel(k)},
          {"faces", r.faces},
          {"samples", r.samples},
          {"tokens", r.tokens},
          {"codes", r.codes},
          {"cycles_rtl", r.rtl_cycles},
          {"cycles_model", r.model_cycles},
          {"held_cycles", r.held_cycles},
          {"vt_hits", r.vt_hits},
          {"checks", r.checks},
          {"mismatches", r.mismatches},
          {"first_mismatch", r.first}};
}

}  // namespace

int CosimCommand::run_invparam() {
  CosimTrace trace(trace_file, trace_cycles, trace_depth, trace_cycles_opt->count() > 0, trace_depth_opt->count() > 0);
  if (input_gaps > 75)
    throw InputError("", "--input-gaps", "at most 75 with --processor invparam (the array would not drain in time)");
  const cosim::IpRtlConfig cfg = pick_config(word_bits, pps);
  const FrameJobs jobs =
      FrameJobs::load(input, frames_text, frame_k, frame_opt->count() > 0, channel, model_limit.limits());
  const std::vector<ScreenFrame> frames = invparam_frames(jobs, input);
  check_outputs(jobs, trace);
  auto rtl = cosim::make_ip_rtl(cfg.w, cfg.n_pp);
  const auto cosim = cosim::make_ip_frame_cosim(*rtl);
  const invparam::ArrayPacing pacing{stall_seed, input_gaps, vt_stalls};
  if (trace.on()) {  // the first frame's cycles 1..C (the model counts them first)
    rtl->trace_to(trace.plan(1, cosim->model_cycles(frames[0], pacing), std::llround(kInvparamDefaultClockNs * 1000),
                             trace_cost(cfg.text()), image_name(jobs, 0)));
  }
  std::cout << "cig cosim: " << input << ", processor invparam, ip_array " << cfg.text() << " (a " << cfg.n_pp << " x "
            << cfg.n_pp << " lattice), stalls: input gaps " << input_gaps << " %, VT stalls " << vt_stalls
            << " % (seed " << stall_seed << ")\n";
  std::cout
      << " frame  ch  faces  samples  tokens   codes  RTL cycles  model cycles    held  mismatches  RTL cycles/s\n";
  nlohmann::ordered_json rep;
  rep["command"] = "cosim";
  rep["input"] = input;
  rep["processor"] = "invparam";
  rep["word_bits"] = cfg.w;
  rep["register_bits"] = cfg.register_bits();
  rep["pixel_processors"] = cfg.n_pp;
  rep["runs"] = nlohmann::ordered_json::array();
  CosimTotals totals;
  Progress progress("cig cosim", (long long)frames.size());
  for (std::size_t k = 0; k < frames.size(); ++k) {
    // Progress by frame: the model runs in lock step with the RTL, so a frame's cycles are known
    // only at its end, and a frame of the built configurations takes about a second.
    const cosim::IpFrameResult r = cosim->run(frames[k], pacing);
    rep["runs"].push_back(frame_row(jobs, k, r));
    totals.add(r.checks, r.mismatches, r.rtl_cycles == r.model_cycles, r.first);
    if (k == 0 && trace.on()) rep["trace"] = trace.finish(cosim::TracedDesign::kInvparamArray, r.seconds);
    progress.step(image_name(jobs, k) + ": " + std::to_string(r.rtl_cycles) + " cycles");
  }
  const int status = totals.finish(rep, "values", "checks", "frame(s)");
  if (!report_file.empty()) write_text_file(report_file, report_text(rep));
  return status;
}

}  // namespace cig::cli
