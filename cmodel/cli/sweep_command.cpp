// cig sweep INPUT --engine E --vary KEY=V1,V2,... [--vary KEY2=...]... [--engine-opt K=V]...
//                 [--reference float|float-snap|float-snap-priority] [--reference-spp N]
//                 [--frame K | --frames A:B] [--channel C] [--repeat R] [--report FILE] [--plot FILE.png]
//                 [--html DIR]
// Run time against error: for every combination of the values of the varied engine options (any
// engine, any option it accepts: samples per pixel, a format, an architecture, ...), renders the
// chosen images (a polygon list, or a scene's frames x channels) with the engine, times the engine
// alone (its render call, best of R repeats per image, one thread), adds up the hardware time its
// model gives (the segment processor's seed timings, the quadtree's cycles at its clock), compares
// its images with the reference's and prints one row: the combination, ms per frame of the model
// and of the modelled hardware, PSNR over all pixels, the largest absolute error of any colour
// channel, the pixels off by more than 2 LSB, the pixels whose polygon id differs, and whether the
// row is on the Pareto frontier of time against PSNR. --plot draws that frontier with gnuplot.
// Every option and value is checked before any work; nothing is printed or written until every
// image is done.
#include "cli/sweep_command.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "cli/frame_jobs.hpp"
#include "cli/gnuplot_plot.hpp"
#include "cli/output_plan.hpp"
#include "cli/review_outputs.hpp"
#include "common/error.hpp"
#include "common/progress.hpp"
#include "image/image.hpp"
#include "registry/engine_registry.hpp"

namespace cig::cli {

void SweepCommand::add_to(CLI::App& app) {
  sub = app.add_subcommand("sweep", "engine run time against image error over combinations of engine options");
  sub->add_option("input", input, "scene or polygon list")->required();
  sub->add_option("--vary", vary, "KEY=V1,V2,...: an engine option to vary and its values (repeatable)")
      ->required()
      ->allow_extra_args(false);
  frame_opt = sub->add_option("--frame", frame_k, "frame number (scenes; default 0)");
  sub->add_option("--frames", frames_text, "inclusive frame range A:B (scenes)")->excludes(frame_opt);
  sub->add_option("--channel", channel, "only this channel (scenes)")->check(CLI::Range(0, kMaxChannelIndex));
  sub->add_option(
      "--reference", reference,
      "float (default), float-snap (vertices snapped to the formatter grid) or float-snap-priority (snapped, visibility by list order as the engines)");
  add_reference_spp(sub, reference_spp);
  sub->add_option("--repeat", repeat, "time each image R times, keep the best (default 3)")->check(CLI::Range(1, 1000));
  sub->add_option("--report", report_file, "write a JSON report");
  sub->add_option("--plot", plot_file, "write PSNR against time, Pareto points marked, as a PNG (gnuplot)");
  sub->add_option("--html", html_dir,
                  "write DIR/index.html: the table, the plot, the report, provenance; the report and the plot go to "
                  "DIR/report.json and DIR/plot.png unless --report and --plot name files (docs/review_outputs.md)");
  engine.add_to(sub);
  model_limit.add_to(sub);
  manager_unit.add_to(sub);
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

// One point of the sweep: a value for every varied key.
struct Combination {
  std::map<std::string, std::string> params;
  std::string label;  // "k1=v1 k2=v2"
};

// Every combination, the first key varying slowest; keys distinct and not set by --engine-opt.
std::vector<Combination> combinations(const std::vector<Varied>& varied, const EngineOptions& base) {
  std::vector<Combination> out(1);
  std::set<std::string> keys;
  for (const Varied& v : varied) {
    if (!keys.insert(v.key).second) throw InputError("", "--vary", "'" + v.key + "' is varied twice");
    if (base.params.count(v.key))
      throw InputError("", "--vary", "'" + v.key + "' is also set by --engine-opt (or a shorthand)");
    std::vector<Combination> next;
    for (const Combination& c : out)
      for (const std::string& value : v.values) {
        Combination d = c;
        d.params[v.key] = value;
        d.label += (d.label.empty() ? "" : " ") + v.key + "=" + value;
        next.push_back(d);
      }
    out = std::move(next);
  }
  return out;
}

struct SweepRow {
  std::string label;
  double engine_ms = 0;    // sum over images of the best time
  double hardware_ms = 0;  // sum over images of the modelled hardware time
  bool has_hardware = true;
  bool pareto = false;
  ComparisonTotals totals;
};

// One engine per combination (each checked against the frames by run()).
std::vector<std::unique_ptr<RasterEngine>> make_engines(const SweepCommand& c, const EngineOptions& base,
                                                        const std::vector<Combination>& combos) {
  std::vector<std::unique_ptr<RasterEngine>> engines;
  for (const Combination& combo : combos) {
    EngineOptions o = base;
    for (const auto& [k, v] : combo.params) o.params[k] = v;
    try {
      engines.push_back(make_engine(c.engine.engine, o));
    } catch (const InputError& e) { throw InputError("", "--vary", combo.label + ": " + e.rule()); }
  }
  return engines;
}

// Image by image: the reference once, then every combination R times (timed: the render call
// alone).
std::vector<SweepRow> measure(const FrameJobs& jobs, const std::vector<Combination>& combos, const EngineOptions& ro,
                              std::vector<std::unique_ptr<RasterEngine>>& engines, int repeat) {
  std::vector<SweepRow> rows(combos.size());
  for (std::size_t v = 0; v < rows.size(); ++v) rows[v].label = combos[v].label;
  auto ref = make_engine(reference_engine_name(), ro);
  Progress progress("cig sweep", (long long)(jobs.size() * rows.size()));
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
      if (got.report.contains("hardware_ms")) rows[v].hardware_ms += got.report["hardware_ms"].get<double>();
      else rows[v].has_hardware = false;
      rows[v].totals.add(compare_run(jobs.frame(k), jobs.channel(k), got.out, want.out));
      const std::string image =
          rows[v].label + ", frame " + std::to_string(jobs.frame(k)) + " channel " + std::to_string(jobs.channel(k));
      progress.note(drop_warning(got.report, image));
      progress.step(image);
    }
  }
  return rows;
}

// The time the frontier is drawn against: the modelled hardware's when every row has one (the
// quantity a hardware architect trades), else the C model's.
bool frontier_uses_hardware(const std::vector<SweepRow>& rows) {
  return std::all_of(rows.begin(), rows.end(), [](const SweepRow& r) { return r.has_hardware; });
}
double frontier_time(const SweepRow& r, bool hardware) { return hardware ? r.hardware_ms : r.engine_ms; }

// Pareto: no other row is at least as fast and at least as accurate, and better in one.
void mark_pareto(std::vector<SweepRow>& rows) {
  const bool hw = frontier_uses_hardware(rows);
  for (SweepRow& a : rows) {
    a.pareto = true;
    for (const SweepRow& b : rows) {
      const double ta = frontier_time(a, hw), tb = frontier_time(b, hw);
      const double pa = a.totals.all.psnr(), pb = b.totals.all.psnr();
      if (&a != &b && tb <= ta && pb >= pa && (tb < ta || pb > pa)) a.pareto = false;
    }
  }
}

nlohmann::ordered_json to_json(const SweepRow& r, const FrameJobs& jobs) {
  const ImageError& e = r.totals.all;
  nlohmann::ordered_json j = {{"value", r.label},
                              {"ms_per_frame", r.engine_ms / jobs.frames()},
                              {"ms_per_image", r.engine_ms / double(jobs.size())}};
  if (r.has_hardware) j["hardware_ms_per_frame"] = r.hardware_ms / jobs.frames();
  j["psnr"] = e.psnr();
  j["psnr_min"] = r.totals.min_psnr;
  j["ssim"] = ssim_json(e.ssim());  // the mean over images
  j["ssim_min"] = ssim_json(e.has_ssim() ? r.totals.min_ssim : e.ssim());
  j["max_abs"] = {e.max_abs[0], e.max_abs[1], e.max_abs[2]};
  j["pixels_over_2lsb"] = e.pixels_over_2lsb;
  j["ids_differ"] = r.totals.ids_differ;
  j["pixels"] = e.pixels;
  j["pareto"] = r.pareto;
  return j;
}

std::string table_text(const SweepCommand& c, const std::vector<SweepRow>& rows, const FrameJobs& jobs) {
  std::size_t width = 6;
  for (const SweepRow& r : rows) width = std::max(width, r.label.size());
  std::ostringstream t;
  t << "cig sweep: engine " << c.engine.engine << " against " << c.reference << " (" << c.reference_spp
    << " samples per pixel) on " << c.input << "\n  " << jobs.frames() << " frame(s) x " << jobs.channels()
    << " channel(s) = " << jobs.size() << " image(s); engine time per image: best of " << c.repeat
    << "; * = Pareto frontier of " << (frontier_uses_hardware(rows) ? "hardware" : "model") << " time against PSNR\n"
    << std::left << std::setw(int(width)) << "options" << std::right
    << "  ms/frame  hw ms/frame     PSNR  max abs   >2 LSB  ids differ\n";
  for (const SweepRow& r : rows) {
    const ImageError& e = r.totals.all;
    std::ostringstream hw;
    if (r.has_hardware) hw << std::fixed << std::setprecision(2) << r.hardware_ms / jobs.frames();
    else hw << "-";
    t << std::left << std::setw(int(width)) << r.label << std::right << std::fixed << std::setprecision(2)
      << std::setw(10) << r.engine_ms / jobs.frames() << std::setw(13) << hw.str() << std::setw(9) << e.psnr()
      << std::setw(9) << r.totals.max_abs() << std::setw(9) << e.pixels_over_2lsb << std::setw(12)
      << r.totals.ids_differ << (r.pareto ? " *" : "") << "\n";
  }
  return t.str();
}

// PSNR against time, every row a point, the Pareto rows joined and labelled (gnuplot_plot.hpp).
void write_plot(const std::string& plot_file, const std::vector<SweepRow>& rows, const FrameJobs& jobs,
                const std::string& title) {
  const bool hw = frontier_uses_hardware(rows);
  const GnuplotJob job("sweep");
  std::vector<const SweepRow*> sorted;
  for (const SweepRow& r : rows) sorted.push_back(&r);
  std::sort(sorted.begin(), sorted.end(),
            [&](const SweepRow* a, const SweepRow* b) { return frontier_time(*a, hw) < frontier_time(*b, hw); });
  {
    std::ofstream all(job.file("all.dat")), front(job.file("pareto.dat"));
    for (const SweepRow* r : sorted) {
      const double t = frontier_time(*r, hw) / jobs.frames(), p = r->totals.all.psnr();
      all << t << " " << p << "\n";
      if (r->pareto) front << t << " " << p << " \"" << r->label << "\"\n";
    }
  }
  std::ostringstream gp;
  gp << "set title \"" << title << "\" noenhanced\nset xlabel '" << (hw ? "modelled hardware" : "C model")
     << " ms per frame'\nset ylabel 'PSNR against the reference (dB)'\nset logscale x\n"
     << "set grid\nset key bottom right\nplot '" << job.file("all.dat")
     << "' using 1:2 with points pt 7 ps 1 title 'configurations', '" << job.file("pareto.dat")
     << "' using 1:2 with linespoints pt 6 ps 2 lw 2 title 'Pareto frontier', '" << job.file("pareto.dat")
     << "' using 1:2:3 with labels offset 1,-1 left font ',8' noenhanced notitle\n";
  job.draw(gp.str(), 1000, 640, plot_file, "--plot");
}

}  // namespace

int SweepCommand::run() {
  // Everything that can be wrong is checked before any work.
  const EngineOptions base = engine.options();
  std::vector<Varied> varied;
  for (const std::string& v : vary) varied.push_back(parse_vary(v));
  const std::vector<Combination> combos = combinations(varied, base);
  EngineOptions ro = reference_options(reference, reference_spp);
  ro.fan_split = base.fan_split;  // the reference follows the engines' polygon split
  std::vector<std::unique_ptr<RasterEngine>> engines = make_engines(*this, base, combos);
  // Each engine's capacity: on a polygon list's counts once parsed, then on every image.
  const auto for_each_engine = [&](const auto& check) {
    for (std::size_t v = 0; v < engines.size(); ++v) {
      try {
        check(*engines[v]);
      } catch (const InputError& e) { throw InputError(e.file(), "--vary", combos[v].label + ": " + e.rule()); }
    }
  };
  const FrameJobs jobs = FrameJobs::load(input, frames_text, frame_k, frame_opt->count() > 0, channel,
                                         model_limit.limits(), manager_unit.arith(),
                                         [&](const ScreenFrame& head, std::size_t polygons, std::size_t light_points) {
                                           for_each_engine([&](const RasterEngine& e) {
                                             FrameJobs::list_capacity(input, e)(head, polygons, light_points);
                                           });
                                         });
  for_each_engine([&](const RasterEngine& e) { jobs.check_capacity(e); });
  if (!html_dir.empty()) prepare_sweep_html(html_dir, report_file, plot_file);
  OutputPlan plan;
  jobs.declare_inputs(plan);
  if (!html_dir.empty()) plan.folder(html_dir, "--html", {"index.html"});
  if (!report_file.empty()) plan.file(report_file, "--report");
  if (!plot_file.empty()) plan.file(plot_file, "--plot");
  plan.check();
  check_plot_output(plot_file, "--plot");
  std::vector<SweepRow> rows = measure(jobs, combos, ro, engines, repeat);
  mark_pareto(rows);

  nlohmann::ordered_json rep;
  rep["command"] = "sweep";
  rep["input"] = input;
  rep["engine"] = engine.engine;
  rep["engine_options"] = base.params;
  rep["vary"] = vary;
  rep["reference"] = reference;
  rep["reference_spp"] = reference_spp;
  rep["frames"] = jobs.frames();
  rep["channels"] = jobs.channels();
  rep["images"] = jobs.size();
  rep["repeat"] = repeat;
  rep["frontier_time"] = frontier_uses_hardware(rows) ? "hardware" : "model";
  rep["rows"] = nlohmann::ordered_json::array();
  for (const SweepRow& r : rows) rep["rows"].push_back(to_json(r, jobs));
  if (!plot_file.empty())
    write_plot(plot_file, rows, jobs,
               "cig sweep " + engine.engine + " on " + input + " against " + reference + " at " +
                   std::to_string(reference_spp) + " samples per pixel");
  if (!report_file.empty()) write_text_file(report_file, report_text(rep));
  const std::string table = table_text(*this, rows, jobs);
  if (!html_dir.empty()) write_sweep_html(html_dir, report_file, plot_file, rep, table);
  std::cout << table;
  return 0;
}

}  // namespace cig::cli
