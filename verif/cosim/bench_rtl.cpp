// Google Benchmark of the Verilated quadtree RTL (rtl/qt_raster.sv) alone, without the model:
// simulated cycles per second and polygons per second of wall time, for
//   * random/6p, random/4p2t: 150 random polygons on a 64-line raster (test_cosim's kind);
//   * overlap/6p: scenes/small/overlap.polys.json;
//   * airfield/9p, airfield/7p2t: the centre channel of frame 0 of scenes/airfield.json;
//   * depth10/9p: scenes/stress/depth10.polys.json.
// The setup kernel's level-0 windows are built once (not timed); each iteration runs one frame:
// the table writes (the fog table only the first time), the frame, the read-out of every pixel.
// The cycles/s counter counts the frame's cycles only, over the whole iteration's time.
// Built by the default build, not run by ctest (a smoke test runs one quick case):
//   build/bin/bench_rtl [--benchmark_filter=REGEX]
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "cosim.hpp"
#include "frame/screen_frame.hpp"
#include "pipeline/scene_pipeline.hpp"
#include "scene/scene_loader.hpp"

namespace {

using cig::ScreenFrame;
using Roots = std::vector<cig::hls::QuadWindow<cig::cosim::RtlArith>>;

std::string source_path(const std::string& relative) { return std::string(CIG_SOURCE_DIR) + "/" + relative; }

ScreenFrame random_frame() {
  std::mt19937_64 r(2);
  auto u = [&](double a, double b) { return a + (b - a) * double(r() >> 11) * 0x1.0p-53; };
  ScreenFrame f;
  f.raster = 64;
  f.fog.colour = {0.5, 0.5, 0.55};
  f.fog.start = 20;
  f.fog.end = 300;
  for (int k = 0; k < 150; ++k) {
    cig::ScreenPolygon p;
    const double cx = u(-0.8, 0.8), cy = u(-0.8, 0.8), s = u(0.02, 0.5);
    const double z = 10 + k;
    p.vertices = {{cx - s, cy - s, z, u(0.2, 1)}, {cx + s, cy - s * 0.5, z + 1, u(0.2, 1)}, {cx, cy + s, z + 2, u(0.2, 1)}};
    p.colour = {u(0.1, 1), u(0.1, 1), u(0.1, 1)};
    f.polygons.push_back(p);
  }
  return f;
}

ScreenFrame airfield_frame() {
  const cig::Scene scene = cig::load_scene(source_path("scenes/airfield.json"));
  const cig::ScenePipeline pipeline(scene);
  nlohmann::ordered_json unused;
  return pipeline.geometry(0, 1, unused);
}

void run_rtl(benchmark::State& state, const ScreenFrame& frame, int raster_log2, int tree_levels) {
  auto rtl = cig::cosim::make_rtl_runner(raster_log2, tree_levels);
  if (!rtl) {
    state.SkipWithError("this build has no such RTL configuration");
    return;
  }
  cig::quad::FrontEndStats fe;
  const Roots roots = cig::quad::front_end<cig::cosim::RtlArith>(frame, raster_log2, fe);
  cig::quad::PixelFrame<cig::cosim::RtlArith> pixels;
  pixels.begin(frame, raster_log2);
  double cycles = 0;
  for (auto _ : state) {
    const cig::cosim::Trace t = rtl->run(roots, pixels, {}, 200000000);
    cycles = double(t.cycles);
    benchmark::DoNotOptimize(t.image.rgb.data());
  }
  const double n = double(state.iterations());
  state.counters["cycles/s"] = benchmark::Counter(cycles * n, benchmark::Counter::kIsRate);
  state.counters["polygons/s"] = benchmark::Counter(double(frame.polygons.size()) * n, benchmark::Counter::kIsRate);
  state.counters["cycles"] = cycles;
  state.counters["root_windows"] = double(roots.size());
}

void register_all() {
  static const ScreenFrame random = random_frame();
  static const ScreenFrame overlap = cig::load_polygon_list(source_path("scenes/small/overlap.polys.json"));
  static const ScreenFrame airfield = airfield_frame();
  static const ScreenFrame depth10 = cig::load_polygon_list(source_path("scenes/stress/depth10.polys.json"));
  struct Case {
    const char* name;
    const ScreenFrame* frame;
    int n, t;
  };
  for (const Case& c : {Case{"rtl/random/6p", &random, 6, 1}, Case{"rtl/random/4p2t", &random, 6, 2}, Case{"rtl/overlap/6p", &overlap, 6, 1},
                        Case{"rtl/airfield/9p", &airfield, 9, 1}, Case{"rtl/airfield/7p2t", &airfield, 9, 2},
                        Case{"rtl/depth10/9p", &depth10, 9, 1}})
    benchmark::RegisterBenchmark(c.name, [c](benchmark::State& s) { run_rtl(s, *c.frame, c.n, c.t); })
        ->Unit(benchmark::kMillisecond)
        ->MeasureProcessCPUTime()
        ->UseRealTime();
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
