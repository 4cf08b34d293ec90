// Google Benchmark of the segment processor as a raster engine: the bit-accurate engine in each
// format (coarse, medium, fine), its double twin, and the float reference for comparison, on
//   * airfield: one channel (centre) of frame 0 of scenes/airfield.json, the screen polygon list
//     built once by the scene pipeline (stages A and B are not timed);
//   * overload: scenes/stress/overload.polys.json (more than 2 x 48K segments: the overload
//     protection drops the smallest polygons).
// Counters (per second of wall time): polygons/s (polygons in the list), segments/s (segments the
// engine generated: polygons' and light points'; 0 for the reference, which has none) and pixels/s.
// Built by the default build, not run by ctest (a smoke test runs one quick case):
//   build/bin/bench_segment [--benchmark_filter=REGEX]
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bench_inputs.hpp"
#include "engine/engine.hpp"
#include "registry/engine_registry.hpp"

namespace {

using cig::ScreenFrame;
using cig::bench::airfield_frame;
using cig::bench::overload_frame;

struct Case {
  std::string name, engine;
  cig::EngineOptions options;
};

void run_engine(benchmark::State& state, const Case& c, const ScreenFrame& (*frame)()) {
  const ScreenFrame& f = frame();
  auto engine = cig::make_engine(c.engine, c.options);
  double segments = 0;
  for (auto _ : state) {
    cig::EngineRun run = engine->render(f);
    benchmark::DoNotOptimize(run.out.image.rgb.data());
    const auto& rep = run.report;
    segments = rep.contains("segments")
                   ? rep["segments"]["polygon"].get<double>() + rep["segments"]["light"].get<double>()
                   : 0.0;
  }
  const double n = double(state.iterations());
  state.counters["polygons/s"] = benchmark::Counter(double(f.polygons.size()) * n, benchmark::Counter::kIsRate);
  state.counters["segments/s"] = benchmark::Counter(segments * n, benchmark::Counter::kIsRate);
  state.counters["pixels/s"] = benchmark::Counter(double(f.raster) * f.raster * n, benchmark::Counter::kIsRate);
}

void register_all() {
  cig::EngineOptions snap;
  snap.snap = true;
  std::vector<Case> cases = {
      {"segment-double", "segment-double", {}}, {"float", "float", {}}, {"float-snap", "float", snap}};
  for (const char* format : {"coarse", "medium", "fine"}) {
    cig::EngineOptions o;
    o.params["format"] = format;
    cases.insert(cases.begin() + (cases.size() - 3), {std::string("segment-") + format, "segment", o});
  }
  const std::vector<std::pair<std::string, const ScreenFrame& (*)()>> inputs = {{"airfield", &airfield_frame},
                                                                                {"overload", &overload_frame}};
  for (const auto& [input, frame] : inputs)
    for (const Case& c : cases)
      cig::bench::register_case(
          c.name + "/" + input, [c, frame = frame](benchmark::State& s) { run_engine(s, c, frame); }, false);
}

}  // namespace

int main(int argc, char** argv) { return cig::bench::run_benchmarks(argc, argv, register_all); }
