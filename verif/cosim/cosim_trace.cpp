#include "cosim_trace.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <stdexcept>

#include "cli/cli_common.hpp"
#include "cli/output_plan.hpp"
#include "common/error.hpp"

namespace cig::cli {

TraceCost trace_cost(const std::string& configuration) {
  // Bytes and seconds per traced cycle, measured (verif/cosim/README.md "Tracing"): the quadtree's
  // 512-line configurations on airfield frame 0, channel 1 (7p2t: the whole frame, 883 MB, about
  // 95 s more on an idle machine; 9p: cycles 20000:29999), its 64-line ones on the whole of
  // scenes/small/overlap.polys.json, stage F's on scenes/polyhedra.json frame 0 (80- and 73-bit
  // registers, 2026-11-27). The bytes follow the signals that change, so they are typical figures;
  // the seconds are what the trace adds to the run, on the shared 2-core machine (at a load of 4 to
  // 6 but for 7p2t's; stage F's at about 2).
  static const std::map<std::string, TraceCost> costs = {
      {"6p", {2200, 2.0e-4}},          {"4p2t", {8000, 9.0e-4}},        {"9p", {1600, 5.5e-4}},
      {"7p2t", {6900, 7.5e-4}},        {"W=64, N_PP=8", {120, 2.9e-5}}, {"W=64, N_PP=64", {870, 2.3e-4}},
      {"W=57, N_PP=16", {230, 5.3e-5}}};
  const auto it = costs.find(configuration);
  return it == costs.end() ? TraceCost{6900, 7.5e-4} : it->second;
}

namespace {

long long parse_cycle(const std::string& text, const std::string& whole) {
  std::size_t used = 0;
  long long v = -1;
  try {
    v = std::stoll(text, &used);
  } catch (const std::logic_error&) { used = 0; }
  if (text.empty() || used != text.size() || v < 0 || text[0] == '+' || text[0] == '-')
    throw InputError("", "--trace-cycles", "'" + whole + "' is not of the form A:B (inclusive cycle numbers, A <= B)");
  return v;
}

std::string megabytes(double bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, bytes < 10e6 ? "%.1f MB" : "%.0f MB", bytes / 1e6);
  return buf;
}

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, s < 10 ? "%.1f s" : "%.0f s", s);
  return buf;
}

// A trace this large warns first (the whole airfield frame at 7p2t: about 900 MB and 90 s).
constexpr double kWarnBytes = 50e6;
constexpr double kWarnSeconds = 10;
constexpr long long kSuggestedWindow = 2000;

}  // namespace

CosimTrace::CosimTrace(std::string file, const std::string& cycles_text, int depth, bool cycles_given, bool depth_given)
    : file_(std::move(file)), depth_(depth) {
  if (cycles_given && file_.empty())
    throw InputError("", "--trace-cycles", "needs --trace FILE.fst (the window is of the traced image's cycles)");
  if (depth_given && file_.empty()) throw InputError("", "--trace-depth", "needs --trace FILE.fst");
  if (!cycles_given) return;
  const std::size_t colon = cycles_text.find(':');
  if (colon == std::string::npos)
    throw InputError("", "--trace-cycles",
                     "'" + cycles_text + "' is not of the form A:B (inclusive cycle numbers, A <= B)");
  first_ = parse_cycle(cycles_text.substr(0, colon), cycles_text);
  last_ = parse_cycle(cycles_text.substr(colon + 1), cycles_text);
  if (last_ < first_)
    throw InputError("", "--trace-cycles", "'" + cycles_text + "': B < A (the window is cycles A to B, inclusive)");
}

void CosimTrace::declare_outputs(OutputPlan& plan) const {
  if (!on()) return;
  plan.file(file_, "--trace");
  plan.file(save_file(), "--trace");
}

cosim::TraceSettings CosimTrace::plan(long long first_cycle, long long last_cycle, std::int64_t period_ps,
                                      const TraceCost& cost, const std::string& image) {
  const bool window = first_ >= 0;
  if (window && (first_ < first_cycle || last_ > last_cycle))
    throw InputError("", "--trace-cycles",
                     "cycles " + std::to_string(first_) + ":" + std::to_string(last_) + " are outside the cycles of " +
                         image + ", " + std::to_string(first_cycle) + ":" + std::to_string(last_cycle) +
                         " (the image the trace holds, the first one run)");
  settings_.file = file_;
  settings_.first = window ? first_ : first_cycle;
  settings_.last = window ? last_ : last_cycle;
  settings_.period_ps = period_ps;
  settings_.depth = depth_;
  image_ = image;
  const double cycles = double(settings_.last - settings_.first + 1);
  const double bytes = cycles * cost.bytes_per_cycle, seconds = cycles * cost.seconds_per_cycle;
  if (bytes > kWarnBytes || seconds > kWarnSeconds)
    std::cerr << "cig: warning: --trace: cycles " << settings_.first << ":" << settings_.last << " of " << image
              << (window ? "" : " (the whole image)") << " will write about " << megabytes(bytes) << " to " << file_
              << " and take about " << seconds_text(seconds) << " more; --trace-cycles A:B traces a window ("
              << kSuggestedWindow << " cycles: about " << megabytes(double(kSuggestedWindow) * cost.bytes_per_cycle)
              << ", " << seconds_text(double(kSuggestedWindow) * cost.seconds_per_cycle) << ")\n";
  const auto parent = std::filesystem::path(file_).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  return settings_;
}

nlohmann::ordered_json CosimTrace::finish(cosim::TracedDesign design, double image_seconds) const {
  const cosim::FstContents fst = cosim::read_fst_contents(file_);
  const std::vector<cosim::GtkwGroup> groups = cosim::design_groups(design, fst.signals);
  const int picked = cosim::write_gtkw(save_file(), file_, fst.start_time, groups);
  const auto bytes = std::filesystem::file_size(file_);
  const cosim::TraceTimeScale scale(settings_.period_ps);
  const std::string unit = std::string(scale.unit).substr(1);
  std::cout << "trace: " << image_ << ", cycles " << settings_.first << ":" << settings_.last << " ("
            << settings_.last - settings_.first + 1 << " cycles of " << scale.period << " " << unit << "; FST time "
            << fst.start_time << ".." << fst.end_time << " " << unit << "): " << file_ << " ("
            << megabytes(double(bytes)) << ", " << fst.signals.size() << " signals"
            << (depth_ > 0 ? ", depth " + std::to_string(depth_) : std::string()) << "), save file " << save_file()
            << " (" << picked << " signals grouped)\n";
  return {{"file", file_},
          {"save_file", save_file()},
          {"image", image_},
          {"first_cycle", settings_.first},
          {"last_cycle", settings_.last},
          {"period_ps", settings_.period_ps},
          {"time_unit", unit},
          {"fst_start_time", fst.start_time},
          {"fst_end_time", fst.end_time},
          {"depth", depth_},
          {"bytes", bytes},
          {"signals", fst.signals.size()},
          {"signals_in_save_file", picked},
          {"image_seconds", image_seconds}};
}

void CosimTrace::discard() const {
  if (!on()) return;
  std::error_code ec;
  std::filesystem::remove(file_, ec);
  std::filesystem::remove(save_file(), ec);
}

}  // namespace cig::cli
