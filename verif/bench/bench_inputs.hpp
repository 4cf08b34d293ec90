// What the Google Benchmark programs share (bench_segment, bench_quadtree, bench_llvmpipe,
// verif/cosim/bench_rtl): their inputs, built on first use so that a filtered run loads only what
// it needs, the registration of a millisecond, wall-time case, and main().
#pragma once

#include <benchmark/benchmark.h>

#include <string>
#include <utility>

#include "frame/screen_frame.hpp"
#include "generator/image_generator.hpp"
#include "scene/scene_loader.hpp"

namespace cig::bench {

inline std::string source_path(const std::string& relative) { return std::string(CIG_SOURCE_DIR) + "/" + relative; }

inline const Scene& airfield_scene() {
  static const Scene scene = load_scene(source_path("scenes/airfield.json"));
  return scene;
}
// One channel of one frame of scenes/airfield.json (stages A and B, run by the caller once: not timed).
inline ScreenFrame airfield_frame(int frame, int channel) {
  const ImageGenerator pipeline(airfield_scene());
  nlohmann::ordered_json unused;
  return pipeline.geometry(frame, channel, unused);
}
// The centre channel of frame 0.
inline const ScreenFrame& airfield_frame() {
  static const ScreenFrame frame = airfield_frame(0, 1);
  return frame;
}
inline const ScreenFrame& depth10_frame() {
  static const ScreenFrame frame = load_polygon_list(source_path("scenes/stress/depth10.polys.json"));
  return frame;
}
inline const ScreenFrame& overload_frame() {
  static const ScreenFrame frame = load_polygon_list(source_path("scenes/stress/overload.polys.json"));
  return frame;
}

// A case in milliseconds of wall time; `process_cpu` also measures the CPU time of every thread.
template <class Fn>
void register_case(const std::string& name, Fn fn, bool process_cpu = true) {
  auto* b = benchmark::RegisterBenchmark(name.c_str(), std::move(fn))->Unit(benchmark::kMillisecond);
  if (process_cpu) b->MeasureProcessCPUTime();
  b->UseRealTime();
}

inline int run_benchmarks(int argc, char** argv, void (*register_all)()) {
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace cig::bench
