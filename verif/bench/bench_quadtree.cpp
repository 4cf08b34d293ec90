// Google Benchmark of the recursive-subdivision raster processor (`--engine quadtree`, run clock
// by clock through the architecture model) as a raster engine, masks on and off, on
//   * airfield: the centre channel of frame 0 of scenes/airfield.json (stages A and B built once,
//     not timed);
//   * depth10: scenes/stress/depth10.polys.json, depth complexity 10 (ten slabs of opaque
//     rectangles, front to back): the case the priority masks are for.
// Counters (per second of wall time): polygons/s (polygons in the list), samples/s (samples the
// pixel processor wrote: covered and visible), windows/s (children the PEs tested) and, as plain
// numbers, the model's cycles per frame and the pixel records the PEs emitted.
// Built by the default build, not run by ctest (a smoke test runs one quick case):
//   build/bin/bench_quadtree [--benchmark_filter=REGEX]
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "bench_inputs.hpp"
#include "engine/engine.hpp"
#include "registry/engine_registry.hpp"

namespace {

using cig::ScreenFrame;
using cig::bench::airfield_frame;
using cig::bench::depth10_frame;

void run_engine(benchmark::State& state, const std::string& engine_name, const cig::EngineOptions& options,
                const ScreenFrame& (*frame)()) {
  const ScreenFrame& f = frame();
  auto engine = cig::make_engine(engine_name, options);
  double samples = 0, windows = 0, cycles = 0, records = 0;
  for (auto _ : state) {
    cig::EngineRun run = engine->render(f);
    benchmark::DoNotOptimize(run.out.image.rgb.data());
    const auto& rep = run.report;
    windows = 0;
    for (const auto& l : rep["levels"]) windows += l["children_tested"].get<double>();
    cycles = rep["cycles"]["frame"].get<double>();
    records = rep["pixel_records"].get<double>();
    samples = rep["samples_written"].get<double>();
  }
  const double n = double(state.iterations());
  state.counters["polygons/s"] = benchmark::Counter(double(f.polygons.size()) * n, benchmark::Counter::kIsRate);
  state.counters["windows/s"] = benchmark::Counter(windows * n, benchmark::Counter::kIsRate);
  state.counters["samples/s"] = benchmark::Counter(samples * n, benchmark::Counter::kIsRate);
  state.counters["cycles"] = cycles;
  state.counters["pixel_records"] = records;
}

void register_all() {
  const std::vector<std::pair<std::string, const ScreenFrame& (*)()>> inputs = {{"airfield", &airfield_frame},
                                                                                {"depth10", &depth10_frame}};
  for (const auto& input_and_frame : inputs) {
    // Named copies: a lambda cannot capture a structured binding in C++17 (clang rejects it).
    const std::string& input = input_and_frame.first;
    const auto frame = input_and_frame.second;
    for (const char* masks : {"on", "off"})
      for (const char* engine : {"quadtree", "quadtree-double"}) {
        cig::EngineOptions o;
        o.params["masks"] = masks;
        const std::string name = std::string(engine) + "/" + input + "/masks-" + masks;
        cig::bench::register_case(name, [=](benchmark::State& s) { run_engine(s, engine, o, frame); });
      }
  }
}

}  // namespace

int main(int argc, char** argv) { return cig::bench::run_benchmarks(argc, argv, register_all); }
