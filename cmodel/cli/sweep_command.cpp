// cig sweep INPUT --engine E --vary KEY=V1,V2,... [--engine-opt K=V]... [--reference float|float-snap]
//                 [--frame K | --frames A:B] [--channel C] [--repeat R] [--report FILE]
// Run time against error: for each value V of the engine option KEY (any engine, any option the
// engine accepts: a format, an architecture, ...), renders the chosen images (a polygon list, or a
// scene's frames x channels) with the engine, times the engine alone (its render call, best of R
// repeats per image, one thread), compares its images with the reference's and prints one row:
// the value, ms per frame (the engine's time for all chosen channels of a frame), PSNR over all
// pixels, the largest absolute error of any colour channel, the pixels off by more than 2 LSB and
// the pixels whose polygon id differs. Every option and value is checked before any work; nothing
// is printed or written until every image is done.
#include "cli/sweep_command.hpp"

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <limits>
#include <set>
#include <sstream>

#include "cli/frame_jobs.hpp"
#include "common/error.hpp"
#include "image/image.hpp"
#include "registry/engine_registry.hpp"

namespace cig::cli {

void SweepCommand::add_to(CLI::App& app) {
  sub = app.add_subcommand("sweep", "engine run time against image error over the values of one engine option");
  sub->add_option("input", input, "scene or polygon list")->required();
  sub->add_option("--vary", vary, "KEY=V1,V2,...: the engine option to vary and its values")->required();
  frame_opt = sub->add_option("--frame", frame_k, "frame number (scenes; default 0)");
  sub->add_option("--frames", frames_text, "inclusive frame range A:B (scenes)")->excludes(frame_opt);
  sub->add_option("--channel", channel, "only this channel (scenes)")->check(CLI::Range(0, kMaxChannelIndex));
  sub->add_option(
      "--reference", reference,
      "float (default), float-snap (vertices snapped to the formatter grid) or float-snap-priority (snapped, visibility by list order as the engines)");
  sub->add_option("--repeat", repeat, "time each image R times, keep the best (default 3)")->check(CLI::Range(1, 1000));
  sub->add_option("--report", report_file, "write a JSON report");
  engine.add_to(sub);
  model_limit.add_to(sub);
  sub->get_option("--engine")->required();
}

namespace {

struct Varied {
  std::string key;
  std::vector<std::string> values;
};

// "KEY=V1,V2,...": a key, then one or more distinct non-empty values.
Varied parse_vary(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    throw InputError("", "--vary", "'" + text + "' is not of the form KEY=V1,V2,...");
  Varied v;
  v.key = text.substr(0, eq);
  std::set<std::string> seen;
  std::stringstream values(text.substr(eq + 1));
  std::string value;
  while (std::getline(values, value, ',')) {
    if (value.empty()) throw InputError("", "--vary", "'" + text + "' has an empty value");
    if (!seen.insert(value).second) throw InputError("", "--vary", "value '" + value + "' appears twice");
    v.values.push_back(value);
  }
  if (text.back() == ',') throw InputError("", "--vary", "'" + text + "' has an empty value");
  return v;
}

struct SweepRow {
  std::string value;
  double engine_ms = 0;  // sum over images of the best time
  ComparisonTotals totals;
};

}  // namespace

namespace {

// One engine per value of the varied option (each checked against the frames by run()).
std::vector<std::unique_ptr<RasterEngine>> make_engines(const SweepCommand& c, const EngineOptions& base,
                                                        const Varied& varied) {
  std::vector<std::unique_ptr<RasterEngine>> engines;
  for (const auto& value : varied.values) {
    EngineOptions o = base;
    o.params[varied.key] = value;
    try {
      engines.push_back(make_engine(c.engine.engine, o));
    } catch (const InputError& e) { throw InputError("", "--vary", varied.key + "=" + value + ": " + e.rule()); }
  }
  return engines;
}

// Image by image: the reference once, then every value R times (timed: the render call alone).
std::vector<SweepRow> measure(const FrameJobs& jobs, const Varied& varied, const EngineOptions& ro,
                              std::vector<std::unique_ptr<RasterEngine>>& engines, int repeat) {
  std::vector<SweepRow> rows(varied.values.size());
  for (std::size_t v = 0; v < rows.size(); ++v) rows[v].value = varied.values[v];
  auto ref = make_engine("float", ro);
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    const ScreenFrame f = jobs.screen_frame(k);
    const EngineRun want = ref->render(f);
    for (std::size_t v = 0; v < rows.size(); ++v) {
      double best = std::numeric_limits<double>::infinity();
      EngineRun got;
      for (int r = 0; r < repeat; ++r) {
        const auto t0 = Clock::now();
        got = engines[v]->render(f);
        best = std::min(best, ms_since(t0));
      }
      rows[v].engine_ms += best;
      rows[v].totals.add(compare_run(jobs.frame(k), jobs.channel(k), got.out, want.out));
    }
    if (jobs.size() > 1) std::cerr << "\rcig: sweep image " << k + 1 << "/" << jobs.size() << std::flush;
  }
  if (jobs.size() > 1) std::cerr << "\n";
  return rows;
}

nlohmann::ordered_json to_json(const SweepRow& r, const FrameJobs& jobs) {
  const ImageError& e = r.totals.all;
  return {{"value", r.value},
          {"ms_per_frame", r.engine_ms / jobs.frames()},
          {"ms_per_image", r.engine_ms / double(jobs.size())},
          {"psnr", e.psnr()},
          {"psnr_min", r.totals.min_psnr},
          {"max_abs", {e.max_abs[0], e.max_abs[1], e.max_abs[2]}},
          {"pixels_over_2lsb", e.pixels_over_2lsb},
          {"ids_differ", r.totals.ids_differ},
          {"pixels", e.pixels}};
}

}  // namespace

int SweepCommand::run() {
  // Everything that can be wrong is checked before any work.
  const EngineOptions base = engine.options();
  const Varied varied = parse_vary(vary);
  if (base.params.count(varied.key))
    throw InputError("", "--vary", "'" + varied.key + "' is also set by --engine-opt (or a shorthand)");
  EngineOptions ro = reference_options(reference);
  ro.fan_split = base.fan_split;  // the reference follows the engines' polygon split
  const FrameJobs jobs =
      FrameJobs::load(input, frames_text, frame_k, frame_opt->count() > 0, channel, model_limit.limits());
  std::vector<std::unique_ptr<RasterEngine>> engines = make_engines(*this, base, varied);
  for (std::size_t v = 0; v < engines.size(); ++v) {
    try {
      jobs.check_capacity(*engines[v]);
    } catch (const InputError& e) {
      throw InputError(e.file(), "--vary", varied.key + "=" + varied.values[v] + ": " + e.rule());
    }
  }
  if (!report_file.empty()) check_output_file(report_file, "--report");
  const std::vector<SweepRow> rows = measure(jobs, varied, ro, engines, repeat);

  const int width = int(std::max<std::size_t>(varied.key.size(), 6));
  std::ostringstream table;
  table << "cig sweep: engine " << engine.engine << ", " << varied.key << " in {";
  for (std::size_t v = 0; v < rows.size(); ++v) table << (v ? ", " : "") << rows[v].value;
  table << "} against " << reference << " on " << input << "\n"
        << "  " << jobs.frames() << " frame(s) x " << jobs.channels() << " channel(s) = " << jobs.size()
        << " image(s); engine time per image: best of " << repeat << "\n"
        << std::left << std::setw(width) << varied.key << std::right
        << "  ms/frame     PSNR  max abs   >2 LSB  ids differ\n";
  nlohmann::ordered_json rep;
  rep["command"] = "sweep";
  rep["input"] = input;
  rep["engine"] = engine.engine;
  rep["engine_options"] = base.params;
  rep["vary"] = varied.key;
  rep["reference"] = reference;
  rep["frames"] = jobs.frames();
  rep["channels"] = jobs.channels();
  rep["images"] = jobs.size();
  rep["repeat"] = repeat;
  rep["rows"] = nlohmann::ordered_json::array();
  for (const SweepRow& r : rows) {
    const ImageError& e = r.totals.all;
    table << std::left << std::setw(width) << r.value << std::right << std::fixed << std::setprecision(2)
          << std::setw(10) << r.engine_ms / jobs.frames() << std::setw(9) << e.psnr() << std::setw(9)
          << r.totals.max_abs() << std::setw(9) << e.pixels_over_2lsb << std::setw(12) << r.totals.ids_differ << "\n";
    rep["rows"].push_back(to_json(r, jobs));
  }
  if (!report_file.empty()) write_text_file(report_file, report_text(rep));
  std::cout << table.str();
  return 0;
}

}  // namespace cig::cli
