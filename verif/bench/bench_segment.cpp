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

#include "engine/engine.hpp"
#include "pipeline/scene_pipeline.hpp"
#include "scene/scene_loader.hpp"

namespace {

using cig::ScreenFrame;

std::string source_path(const std::string& relative) { return std::string(CIG_SOURCE_DIR) + "/" + relative; }

// Built on first use, so that a filtered run loads only what it needs.
const ScreenFrame& airfield_frame() {
  static const ScreenFrame frame = [] {
    static const cig::Scene scene = cig::load_scene(source_path("scenes/airfield.json"));
    const cig::ScenePipeline pipeline(scene);
    nlohmann::ordered_json unused;
    return pipeline.geometry(0, 1, unused);
  }();
  return frame;
}

const ScreenFrame& overload_frame() {
  static const ScreenFrame frame = cig::load_polygon_list(source_path("scenes/stress/overload.polys.json"));
  return frame;
}

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
      benchmark::RegisterBenchmark((c.name + "/" + input).c_str(),
                                   [c, frame = frame](benchmark::State& s) { run_engine(s, c, frame); })
          ->Unit(benchmark::kMillisecond)
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
