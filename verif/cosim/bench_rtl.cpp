// Google Benchmark of the Verilated quadtree RTL (rtl/quadtree/qt_raster.sv) alone, without the
// model: simulated cycles per second and polygons per second of wall time, for
//   * random/6p, random/4p2t: 150 random polygons on a 64-line raster (test_cosim's kind);
//   * overlap/6p: scenes/small/overlap.polys.json;
//   * airfield/9p, airfield/7p2t: the centre channel of frame 0 of scenes/airfield.json;
//   * depth10/9p: scenes/stress/depth10.polys.json;
//   * invparam/polyhedra/w64n64: the inverse-parameter array (ip_array for the seed's 64-bit word,
//     80-bit registers, N_PP = 64, its model Verilated for speed) alone on scenes/polyhedra.json frame 0, centre channel, set up on a
//     64 x 64 lattice; frames back to back without reset; counters cycles/s, faces/s, samples/s.
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
#include "invparam/ip_cosim.hpp"
#include "quadtree/cosim.hpp"

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

// The array's input: the frame's stream (built once, not timed).
struct IpInput {
  std::vector<cig::invparam::StreamCode<64>> stream;
  int columns = 0;
  std::int64_t faces = 0;
  cig::hls::Word<64> eps, tau_near;  // RGeps, RGnear (the scene's near plane)
};
const IpInput& polyhedra_ip_input() {
  static const IpInput input = [] {
    const cig::Scene scene = cig::load_scene(cig::bench::source_path("scenes/polyhedra.json"));
    const cig::ImageGenerator pipeline(scene);
    nlohmann::ordered_json rep;
    const cig::ScreenFrame f = pipeline.geometry(0, 1, rep);
    const cig::InvparamSetup<64> setup = cig::invparam_setup<64>(f, cig::InvparamLattice{64, 0});
    const cig::invparam::InvparamScene<64> s = cig::invparam::scene_of_setup(setup);
    IpInput in;
    in.columns = 64;
    in.stream = cig::invparam::build_frame_stream(s, in.columns, 64, cig::invparam::StreamMode::kFull);
    in.faces = std::int64_t(s.faces.size());
    in.eps = s.eps;
    in.tau_near = s.tau_near;
    return in;
  }();
  return input;
}

void run_ip_rtl(benchmark::State& state) {
  auto rtl = cig::cosim::make_fast_ip_rtl(64, 64);
  if (!rtl) rtl = cig::cosim::make_ip_rtl(64, 64);
  if (!rtl) {
    state.SkipWithError("this build has no such RTL configuration");
    return;
  }
  const IpInput& in = polyhedra_ip_input();
  rtl->reset(cig::cosim::rtl_word<64>(in.eps), cig::cosim::rtl_word<64>(in.tau_near));
  double cycles = 0;
  for (auto _ : state) cycles = double(cig::cosim::ip_rtl_run_frame<64>(*rtl, in.stream, in.columns));
  const double n = double(state.iterations());
  state.counters["cycles/s"] = benchmark::Counter(cycles * n, benchmark::Counter::kIsRate);
  state.counters["faces/s"] = benchmark::Counter(double(in.faces) * n, benchmark::Counter::kIsRate);
  state.counters["samples/s"] = benchmark::Counter(64.0 * in.columns * n, benchmark::Counter::kIsRate);
  state.counters["cycles"] = cycles;
  state.counters["faces"] = double(in.faces);
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
  cig::bench::register_case("rtl/invparam/polyhedra/w64n64", run_ip_rtl);
}

}  // namespace

int main(int argc, char** argv) { return cig::bench::run_benchmarks(argc, argv, register_all); }
