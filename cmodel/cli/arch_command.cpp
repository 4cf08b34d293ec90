// cig arch [--n N | --raster R] [--perf-n N] [--aspects 1,5,10] [--areas LIST] [--positions K]
//          [--archs LIST] [--stream K] [--perf-aspect R] [--perf-rotation 0|45] [--fifo D]
//          [--seed S] [--threads T] [--report FILE.json]
//          [--table nArch|windows|performance|all]
// cig arch --processor invparam [--faces-per-object M] [--objects N1,N2,..] [--columns P]
//          [--pps N_n] [--clock-ns T] [--widths W1,W2,..] [--report FILE.json]
// Seed 004's architecture analysis, measured with the project's kernels and cycle model
// (cmodel/studies/arch_analysis.hpp; discussion and results: docs/results/architecture.md):
//   nArch        eq. 10's N_arch for n = 10 beside Architecture::pe_count and the seed's table;
//   windows      w_i(S) of rectangles (aspects x {0, 45 degrees} x areas) against eq. 2-3;
//   performance  clocks per polygon, P/P_max, speed-up over the stack, eq. 9's load R(S) and the
//                PE utilisation of each architecture, from ArchModel (masks off) and from eq. 5-8;
//                then the seed's own idealisation (eq. 2, 5-9) with its Fig. 4 parameters (alpha = 2,
//                k_p/k_e = 1) and with this project's (alpha = 3/4, t_p = 0).
#include "cli/arch_command.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <functional>
#include <iostream>
#include <mutex>
#include <thread>

#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "image/image.hpp"
#include "studies/arch_analysis.hpp"

namespace cig::cli {

void ArchCommand::add_to(CLI::App& app) {
  sub = app.add_subcommand("arch",
                           "seed 004's architecture analysis (eq. 2-10) measured with the kernels and the cycle model");
  sub->add_option("--n", raster_log2, "windows table: raster of 2^n lines, n = 4..10 (default 9)");
  sub->add_option("--raster", raster, "windows table: the raster as a line count (16..1024), instead of --n");
  sub->add_option("--perf-n", perf_log2, "performance table: raster of 2^n lines (default 10)");
  sub->add_option("--aspects", aspects, "rectangle aspect ratios, each >= 1 (default 1,5,10)")->delimiter(',');
  sub->add_option("--areas", areas, "rectangle areas S in pixels (default 1,10,100,1000)")->delimiter(',');
  sub->add_option("--positions", positions, "windows table: random sub-pixel positions per rectangle (default 256)");
  sub->add_option("--archs", archs, "performance table: architectures (eq. 1; default: the seed's set for the raster)")
      ->delimiter(',');
  sub->add_option("--stream", stream, "performance table: rectangles per area in the stream (default 1024)");
  sub->add_option("--perf-aspect", perf_aspect, "performance table: the rectangles' aspect ratio (default 5)");
  sub->add_option("--perf-rotation", perf_rotation, "performance table: rotation, 0 or 45 degrees (default 45)");
  sub->add_option("--fifo", fifo, "FIFO depth between stages (default 2)");
  sub->add_option("--seed", seed, "random seed of the positions (default 1)");
  sub->add_option("--threads", threads, "worker threads (default: cores)");
  sub->add_option("--report", report_file, "write every table as JSON");
  sub->add_option("--table", table, "nArch, windows, performance or all (default all)");
  sub->add_option("--processor", processor,
                  "quadtree (seed 004, default) or invparam (seed 002's systolic array: frame time, faces/s)");
  sub->add_option("--faces-per-object", faces_per_object, "invparam: m, faces per object (default 6)");
  sub->add_option("--objects", objects, "invparam: n, objects in the scene (default 100,1000,10000,100000)")
      ->delimiter(',');
  sub->add_option("--columns", columns, "invparam: P, columns (default 512)");
  sub->add_option("--pps", pps, "invparam: N_n, pixel processors = samples a column (default 512)");
  sub->add_option("--clock-ns", clock_ns, "invparam: t_t, the PP's clock period in ns (default 3)");
  sub->add_option("--widths", widths, "invparam: mean object widths in columns (default 10,50,100,250,500)")
      ->delimiter(',');
}

namespace {

using nlohmann::ordered_json;
using quad::Architecture;

// Runs fn(0..count-1) on `threads` workers; rethrows the first exception.
void parallel_for(int count, int threads, const std::function<void(int)>& fn) {
  std::atomic<int> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto worker = [&] {
    for (int k = next++; k < count; k = next++) {
      try {
        fn(k);
      } catch (...) {
        std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::min(threads, count); ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// The seed's architectures of Fig. 4 for n = 10, and their analogues at other rasters.
std::vector<std::string> default_archs(int n) {
  if (n == 10) return {"10s", "10p", "10t", "8p2t", "7p3t", "9s1p", "3s3s2s2t"};
  std::vector<std::string> a{"ns", "np", "nt"};
  if (n >= 4) a.push_back(std::to_string(n - 2) + "p2t");
  if (n >= 5) a.push_back(std::to_string(n - 3) + "p3t");
  a.push_back(std::to_string(n - 1) + "s1p");
  return a;
}

void print_pe_table(ordered_json& report) {
  std::printf(
      "== Table 1: N_arch of eq. 10 for n = 10: N_arch = i - 1 + (4^(n-i+1) - 1)/3, the pipeline-tree (i-1)p(n-i+1)t ==\n");
  std::printf("%3s  %-5s %10s %14s %12s %14s  %s\n", "i", "arch", "eq. 10", "pe_count()", "seed table", "eq. 10 (4 sd)",
              "");
  ordered_json rows = ordered_json::array();
  bool all_ok = true;
  for (const quad::SeedPeRow& r : quad::seed_pe_table()) {
    const double r4 = quad::round_significant(double(r.formula), 4);
    const bool ok = r.formula == r.parsed && std::fabs(r4 - r.seed_printed) <= 1e-9 * r.seed_printed;
    all_ok = all_ok && ok;
    std::printf("%3d  %-5s %10lld %14lld %12s %14s  %s\n", r.i, r.arch.c_str(), r.formula, r.parsed,
                r.seed_text.c_str(), fmt(r4 >= 1e4 ? "%.3e" : "%.0f", r4).c_str(), ok ? "agree" : "DIFFER");
    rows.push_back({{"i", r.i},
                    {"arch", r.arch},
                    {"eq10", r.formula},
                    {"pe_count", r.parsed},
                    {"seed_table", r.seed_printed},
                    {"agree", ok}});
  }
  std::printf("%s (SPEC.md's 87,381 and 21,845 are the trees alone: docs/results/architecture.md, Table 1)\n\n",
              all_ok ? "eq. 10, Architecture::pe_count() and the seed's table agree for every i."
                     : "MISMATCH: see the rows marked DIFFER.");
  report["n_arch"] = {{"n", 10}, {"rows", rows}, {"all_agree", all_ok}};
}

}  // namespace

namespace {

// ---- Table 2: windows per level against eq. 2-3 ----

ordered_json to_json(int l, int n, const quad::LevelWindows& lw) {
  return {{"level", l},
          {"window_px", 1 << (n - l)},
          {"mean", lw.mean},
          {"mean_se", lw.mean_se},
          {"max", lw.max},
          {"exact_mean", lw.exact_mean},
          {"exact_max", lw.exact_max},
          {"area_expectation", lw.area_expectation},
          {"conservative_expectation", lw.expectation},
          {"bound", lw.bound},
          {"mean_exceeds_bound", lw.mean > lw.bound},
          {"mean_exceeds_bound_by_3se", lw.mean > lw.bound + 3 * lw.mean_se}};
}

ordered_json to_json(const quad::TestRect& r, ordered_json levels) {
  return {{"shape", r.label()},
          {"aspect", r.nominal_aspect},
          {"rotation_deg", r.rotation_deg},
          {"area_nominal", r.nominal_area},
          {"area", r.area},
          {"aspect_exact", r.aspect},
          {"shape_factor", r.shape_factor(quad::kSampleAperture, quad::kSampleAperture)},
          {"levels", std::move(levels)}};
}

struct ExceedCounts {
  int rows = 0, mean = 0, significant = 0, exact = 0;
};

// One rectangle's rows; counts the rows whose mean exceeds eq. 2.
ordered_json print_window_rows(const quad::WindowTable& t, int n, ExceedCounts& counts) {
  const quad::TestRect& r = t.rect;
  std::printf("\n-- %s, S = %g: grid rectangle %.3f px, aspect %.2f, L_shape %.3f (eq. 2's L for this shape) --\n",
              r.label().c_str(), r.nominal_area, r.area, r.aspect,
              r.shape_factor(quad::kSampleAperture, quad::kSampleAperture));
  std::printf("%5s %7s %9s %7s %6s %9s %9s %9s %9s %10s\n", "level", "window", "mean", "se", "max", "exact", "E_area",
              "E_cons", "bound", "mean/bound");
  ordered_json levels = ordered_json::array();
  for (int l = 1; l <= n; ++l) {
    const quad::LevelWindows& lw = t.level[std::size_t(l)];
    const bool over = lw.mean > lw.bound;
    const bool significant = lw.mean > lw.bound + 3 * lw.mean_se;
    counts.mean += over;
    counts.significant += significant;
    counts.exact += lw.exact_mean > lw.bound;
    ++counts.rows;
    std::printf("%5d %6dpx %9.3f %7.3f %6d %9.3f %9.3f %9.3f %9.3f %9.3f%s\n", l, 1 << (n - l), lw.mean, lw.mean_se,
                lw.max, lw.exact_mean, lw.area_expectation, lw.expectation, lw.bound, lw.mean / lw.bound,
                significant ? " !"
                : over      ? " ~"
                            : "");
    levels.push_back(to_json(l, n, lw));
  }
  return to_json(r, std::move(levels));
}

ordered_json window_table(const ArchCommand& c, const std::vector<quad::TestRect>& rects, int workers) {
  const auto t0 = Clock::now();
  std::vector<quad::WindowTable> tables(rects.size());
  parallel_for(int(rects.size()), workers, [&](int k) {
    tables[std::size_t(k)] = quad::measure_windows(rects[std::size_t(k)], c.positions, c.seed + std::uint32_t(k));
  });
  const int n = c.raster_log2;
  std::printf(
      "== Table 2: windows per level w_i(S) against eq. 2-3, raster %d (n = %d), %d positions per rectangle ==\n",
      1 << n, n, c.positions);
  std::printf(
      "bound: eq. 2 with L = %.3f, alpha = beta = 3/4 pixel; '!' mean above the bound by > 3 se, '~' within 3 se.\n"
      "The columns, E_area, E_cons and why some rows exceed eq. 2: docs/results/architecture.md, Table 2.\n",
      quad::kSeedShapeFactor);
  ordered_json jt = ordered_json::array();
  ExceedCounts counts;
  for (const quad::WindowTable& t : tables) jt.push_back(print_window_rows(t, n, counts));
  std::printf(
      "\nSummary: the measured mean exceeds eq. 2 at %d of %d (shape, S, level) rows (%d by more than 3 se); the\n"
      "exact (ideal-test) mean at %d.\n\n",
      counts.mean, counts.rows, counts.significant, counts.exact);
  return {{"raster_log2", n},
          {"positions", c.positions},
          {"shape_factor_L", quad::kSeedShapeFactor},
          {"alpha", quad::kSampleAperture},
          {"rows_exceeding", counts.mean},
          {"rows_exceeding_by_3se", counts.significant},
          {"rows_exceeding_exact", counts.exact},
          {"rectangles", jt},
          {"ms", ms_since(t0)}};
}

// ---- Table 3: performance and load of the architectures (Fig. 4) ----

// Every (area, architecture) pair run through the cycle model; index area * architectures + arch.
std::vector<quad::ArchMeasurement> measure_architectures(const ArchCommand& c, const std::vector<Architecture>& archs,
                                                         const std::vector<quad::TestRect>& rects, int workers) {
  std::vector<std::vector<quad::AnalysisWindow>> streams(rects.size());
  parallel_for(int(rects.size()), workers, [&](int k) {
    streams[std::size_t(k)] = quad::rect_stream(rects[std::size_t(k)], c.stream, c.seed + 1000u + std::uint32_t(k));
  });
  const int na = int(archs.size());
  std::vector<quad::ArchMeasurement> meas(rects.size() * std::size_t(na));
  // Largest trees first, so that they do not finish last on one worker.
  std::vector<int> order(meas.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = int(k);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return archs[std::size_t(a % na)].pe_count() > archs[std::size_t(b % na)].pe_count();
  });
  parallel_for(int(meas.size()), workers, [&](int j) {
    const int k = order[std::size_t(j)];
    meas[std::size_t(k)] = quad::run_architecture(archs[std::size_t(k % na)], streams[std::size_t(k / na)], c.fifo);
  });
  return meas;
}

struct PerformanceRow {
  const quad::TestRect* rect;
  const quad::ArchMeasurement* m;
  double eq, speed, speed_eq, stall;
  std::vector<double> w;
};

ordered_json to_json(const PerformanceRow& r) {
  const quad::ArchMeasurement& m = *r.m;
  const double pes = double(m.pes);
  return {{"area_nominal", r.rect->nominal_area},
          {"area", r.rect->area},
          {"arch", m.arch},
          {"n_arch", m.pes},
          {"polygons", m.polygons},
          {"cycles", m.cycles},
          {"cycles_per_polygon", m.cycles_per_polygon},
          {"cycles_per_polygon_eq", r.eq},
          {"p", 4.0 / m.cycles_per_polygon},
          {"p_eq", 4.0 / r.eq},
          {"speedup", r.speed},
          {"speedup_eq", r.speed_eq},
          {"load_R", r.speed / pes},
          {"load_R_eq", r.speed_eq / pes},
          {"utilisation", m.utilisation},
          {"busy_cycles", m.busy_cycles},
          {"stall_cycles", m.stall_cycles},
          {"windows_per_level", r.w},
          {"host_s", m.seconds}};
}

// One area's rows: every architecture against the stack (meas[0] of the area).
void print_area_rows(const quad::TestRect& rect, const std::vector<Architecture>& archs,
                     const quad::ArchMeasurement* meas, int n, ordered_json& jrows) {
  const quad::ArchMeasurement& st = meas[0];
  std::vector<double> w;
  for (long long c : st.covered) w.push_back(double(c) / st.polygons);
  const double eq_stack = quad::analytic_cycles_per_polygon(archs[0], w);
  std::string wtext;
  for (std::size_t l = 1; l < w.size(); ++l) wtext += (l > 1 ? " " : "") + fmt(w[l] < 10 ? "%.2f" : "%.0f", w[l]);
  std::printf("S = %g (grid rectangle %.3f px): measured w_1..w_%d = %s\n", rect.nominal_area, rect.area, n,
              wtext.c_str());
  for (std::size_t a = 0; a < archs.size(); ++a) {
    const quad::ArchMeasurement& m = meas[a];
    for (std::size_t l = 0; l < m.covered.size(); ++l)
      if (m.covered[l] != st.covered[l])
        throw std::logic_error("arch: architectures disagree on the windows of the same stream");
    PerformanceRow r{&rect, &m, quad::analytic_cycles_per_polygon(archs[a], w), 0, 0, 0, w};
    const double pes = double(m.pes);
    r.speed = st.cycles_per_polygon / m.cycles_per_polygon;
    r.speed_eq = eq_stack / r.eq;
    r.stall = m.cycles > 0 ? 100.0 * double(m.stall_cycles) / (double(m.cycles) * pes) : 0;
    std::printf("%6g %-9s %7lld %9.2f %9.2f %7.4f %7.4f %8.2f %8.2f %8.4f %8.4f %7.4f %7.3f\n", rect.nominal_area,
                m.arch.c_str(), m.pes, m.cycles_per_polygon, r.eq, 4.0 / m.cycles_per_polygon, 4.0 / r.eq, r.speed,
                r.speed_eq, r.speed / pes, r.speed_eq / pes, m.utilisation, r.stall);
    jrows.push_back(to_json(r));
  }
}

// The seed's own idealisation, eq. 2 windows and eq. 5-9 (its Fig. 4 parameters, or this
// project's alpha = beta = 3/4, t_p = 0): speed-up over the stack / load R per architecture.
ordered_json seed_model_table(const std::vector<Architecture>& archs, const std::vector<quad::TestRect>& rects, int n,
                              double alpha, double tp_over_te, const char* title) {
  std::printf(
      "\n-- The seed's idealisation, %s: w_i from eq. 2 (alpha = beta = %g, L = %.3f), eq. 5-6 with\n"
      "t_p/t_e = %g (t_i = t_e (4 w_(i-1) + (t_p/t_e) w_i)), eq. 8-9: speed-up over the stack / load R --\n",
      title, alpha, quad::kSeedShapeFactor, tp_over_te);
  std::printf("%6s", "S");
  for (const Architecture& a : archs) std::printf(" %15s", a.text.c_str());
  std::printf("\n");
  ordered_json rows = ordered_json::array();
  for (const quad::TestRect& r : rects) {
    const std::vector<double> w = quad::seed_model_windows(n, r.nominal_area, alpha, quad::kSeedShapeFactor);
    const double stack = quad::analytic_cycles_per_polygon(archs[0], w, tp_over_te);
    std::printf("%6g", r.nominal_area);
    for (const Architecture& a : archs) {
      const double t = quad::analytic_cycles_per_polygon(a, w, tp_over_te);
      const double speed = stack / t;
      std::printf(" %7.2f/%-7.3f", speed, speed / double(a.pe_count()));
      rows.push_back({{"area", r.nominal_area},
                      {"arch", a.text},
                      {"p", (4 + tp_over_te) / t},
                      {"speedup", speed},
                      {"load_R", speed / double(a.pe_count())}});
    }
    std::printf("\n");
  }
  return ordered_json{
      {"alpha", alpha}, {"shape_factor_L", quad::kSeedShapeFactor}, {"tp_over_te", tp_over_te}, {"rows", rows}};
}

ordered_json performance_table(const ArchCommand& c, const std::vector<Architecture>& archs,
                               const std::vector<quad::TestRect>& rects, int workers) {
  const auto t0 = Clock::now();
  const int n = c.perf_log2;
  const std::vector<quad::ArchMeasurement> meas = measure_architectures(c, archs, rects, workers);
  std::printf(
      "== Table 3: relative performance and load of the architectures (seed 004 Fig. 4, eq. 5-9), raster %d (n = %d) ==\n",
      1 << n, n);
  std::printf(
      "Stream: %d opaque %s rectangles per area at random positions, masks off, FIFO depth %d; p = P/P_max with\n"
      "P_max = 1/4 polygon per clock; meas: the cycle model, eq: eq. 5-8 with the measured w_i; R = eq. 9's load.\n"
      "Timing model, columns and discussion: docs/results/architecture.md, Table 3.\n",
      c.stream, rects.front().label().c_str(), c.fifo);
  std::printf("%6s %-9s %7s %9s %9s %7s %7s %8s %8s %8s %8s %7s %7s\n", "S", "arch", "N_arch", "clk/poly", "eq", "p",
              "p eq", "speedup", "sp eq", "R", "R eq", "util", "stall%");
  ordered_json jrows = ordered_json::array();
  for (std::size_t k = 0; k < rects.size(); ++k) print_area_rows(rects[k], archs, &meas[k * archs.size()], n, jrows);
  const ordered_json seed_fig4 =
      seed_model_table(archs, rects, n, quad::kSeedFig4Aperture, quad::kSeedFig4TpOverTe, "its Fig. 4 parameters");
  const ordered_json seed_here =
      seed_model_table(archs, rects, n, quad::kSampleAperture, 0.0, "this project's aperture and PE timing");
  std::printf("\n");
  return {{"raster_log2", n},
          {"shape", rects.front().label()},
          {"stream", c.stream},
          {"fifo_depth", c.fifo},
          {"p_max_polygons_per_clock", quad::kSeedMaxPolygonsPerClock},
          {"rows", jrows},
          {"seed_model_fig4", seed_fig4},
          {"seed_model_project", seed_here},
          {"ms", ms_since(t0)}};
}

}  // namespace

// Every option checked before any work or output.
void ArchCommand::check_options() {
  if (table != "nArch" && table != "windows" && table != "performance" && table != "all")
    throw InputError("", "--table", "'" + table + "' is not one of nArch, windows, performance, all");
  if (raster != 0) {
    const int k = hls::raster_log2_of(raster);
    if (k < hls::kMinRasterLog2 || k > hls::kMaxRasterLog2)
      throw InputError("", "--raster", "must be a power of two from 16 to 1024, not " + std::to_string(raster));
    if (sub->count("--n") > 0 && k != raster_log2)
      throw InputError("", "--raster",
                       std::to_string(raster) + " lines is n = " + std::to_string(k) + ", but --n is " +
                           std::to_string(raster_log2));
    raster_log2 = k;
  }
  auto check_n = [](int n, const char* option) {
    if (n < hls::kMinRasterLog2 || n > hls::kMaxRasterLog2)
      throw InputError("", option, "the raster must have 16 to 1024 lines (n = 4..10), not n = " + std::to_string(n));
  };
  check_n(raster_log2, "--n");
  check_n(perf_log2, "--perf-n");
  if (positions < 1 || positions > 1000000) throw InputError("", "--positions", "must be 1..1000000");
  if (stream < 1 || stream > hls::kMaxPolygonIds)
    throw InputError("", "--stream", "must be 1..65536 (polygon ids are 16 bits)");
  if (fifo < 1 || fifo > 64) throw InputError("", "--fifo", "must be 1..64");
  if (threads < 0 || threads > 64) throw InputError("", "--threads", "must be 0 (cores) to 64");
  if (perf_rotation != 0 && perf_rotation != 45) throw InputError("", "--perf-rotation", "must be 0 or 45");
  if (aspects.empty()) throw InputError("", "--aspects", "needs at least one aspect ratio");
  if (areas.empty()) throw InputError("", "--areas", "needs at least one area");
  if (!(perf_aspect >= 1)) throw InputError("", "--perf-aspect", "an aspect ratio must be a number >= 1");
  if (!report_file.empty()) check_output_file(report_file, "--report");  // now, not after the work
}

int ArchCommand::run() {
  if (parse_processor(processor) == HardwareProcessor::kInvparam) return run_invparam();
  for (const char* o : {"--faces-per-object", "--objects", "--columns", "--pps", "--clock-ns", "--widths"})
    if (sub->count(o) > 0) throw InputError("", o, "needs --processor invparam");
  check_options();
  const bool want_pe = table == "nArch" || table == "all";
  const bool want_windows = table == "windows" || table == "all";
  const bool want_perf = table == "performance" || table == "all";
  const int workers = threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));

  std::vector<quad::TestRect> window_rects;  // aspect-major, then rotation, then area
  if (want_windows)
    for (double a : aspects)
      for (int rot : {0, 45})
        for (double s : areas) window_rects.push_back(quad::make_test_rect(raster_log2, s, a, rot, "--areas"));
  std::vector<Architecture> arch_list;  // the stack first: the reference of speed-up and eq. 9
  std::vector<quad::TestRect> perf_rects;
  if (want_perf) {
    if (archs.empty()) archs = default_archs(perf_log2);
    arch_list.push_back(Architecture::parse("ns", perf_log2, "--archs"));
    for (const std::string& text : archs) {
      const Architecture a = Architecture::parse(text, perf_log2, "--archs");
      bool seen = false;
      for (const Architecture& b : arch_list) seen = seen || b.text == a.text;
      if (!seen) arch_list.push_back(a);
    }
    for (double s : areas)
      perf_rects.push_back(quad::make_test_rect(perf_log2, s, perf_aspect, perf_rotation, "--areas"));
  }

  ordered_json report;
  report["command"] = "arch";
  const auto t_all = Clock::now();
  if (want_pe) print_pe_table(report);
  if (want_windows) report["windows"] = window_table(*this, window_rects, workers);
  if (want_perf) report["performance"] = performance_table(*this, arch_list, perf_rects, workers);
  report["total_ms"] = ms_since(t_all);
  if (!report_file.empty()) write_text_file(report_file, report_text(report));
  std::printf("cig: arch analysis in %.1f s%s%s\n", ms_since(t_all) / 1000, report_file.empty() ? "" : ", report ",
              report_file.c_str());
  return 0;
}

}  // namespace cig::cli
