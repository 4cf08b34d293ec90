// Google Benchmark of the Verilated quadtree RTL (rtl/qt_raster.sv) alone, without the model:
// simulated cycles per second and polygons per second of wall time, for
//   * random/6p, random/4p2t: 150 random polygons on a 64-line raster (test_cosim's kind);
//   * overlap/6p: scenes/small/overlap.polys.json;
//   * airfield/9p, airfield/7p2t: the centre channel of frame 0 of scenes/airfield.json;
//   * depth10/9p: scenes/stress/depth10.polys.json.
// The setup kernel's level-0 windows are built once (not timed); each iteration runs one frame:
// the table writes (the fog table only the first time), the frame, the read-out of every pixel.
// The cycles/s counter counts the frame's cycles only, over the whole iteration's time.
// 9p and 7p2t run the models Verilated for speed (verif/cosim/CMakeLists.txt, cig_rtl_bench_models),
// the 64-line cases the co-simulation's (FST tracing compiled in, assertions on).
// Built by the default build, not run by ctest (a smoke test runs one quick case):
//   build/bin/bench_rtl [--benchmark_filter=REGEX]
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "bench/bench_inputs.hpp"
#include "cosim.hpp"

namespace {

using cig::ScreenFrame;
using Roots = std::vector<cig::hls::QuadWindow<cig::cosim::RtlArith>>;

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
    p.vertices = {
        {cx - s, cy - s, z, u(0.2, 1)}, {cx + s, cy - s * 0.5, z + 1, u(0.2, 1)}, {cx, cy + s, z + 2, u(0.2, 1)}};
    p.colour = {u(0.1, 1), u(0.1, 1), u(0.1, 1)};
    f.polygons.push_back(p);
  }
  return f;
}

// Built on first use (a filtered run loads only what it needs).
const ScreenFrame& random150_frame() {
  static const ScreenFrame frame = random_frame();
  return frame;
}
const ScreenFrame& overlap_frame() {
  static const ScreenFrame frame = cig::load_polygon_list(cig::bench::source_path("scenes/small/overlap.polys.json"));
  return frame;
}

void run_rtl(benchmark::State& state, const ScreenFrame& (*input)(), int raster_log2, int tree_levels) {
  const ScreenFrame& frame = input();
  // The models Verilated for speed where the build has them (9p, 7p2t), else the co-simulation's.
  auto rtl = cig::cosim::make_fast_rtl_runner(raster_log2, tree_levels);
  if (!rtl) rtl = cig::cosim::make_rtl_runner(raster_log2, tree_levels);
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
  struct Case {
    const char* name;
    const ScreenFrame& (*frame)();
    int n, t;
  };
  for (const Case& c :
       {Case{"rtl/random/6p", &random150_frame, 6, 1}, Case{"rtl/random/4p2t", &random150_frame, 6, 2},
        Case{"rtl/overlap/6p", &overlap_frame, 6, 1}, Case{"rtl/airfield/9p", &cig::bench::airfield_frame, 9, 1},
        Case{"rtl/airfield/7p2t", &cig::bench::airfield_frame, 9, 2},
        Case{"rtl/depth10/9p", &cig::bench::depth10_frame, 9, 1}})
    cig::bench::register_case(c.name, [c](benchmark::State& s) { run_rtl(s, c.frame, c.n, c.t); });
}

}  // namespace

int main(int argc, char** argv) { return cig::bench::run_benchmarks(argc, argv, register_all); }
