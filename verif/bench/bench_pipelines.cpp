// Seed 000's rendering channels: one channel of the airfield (frame 5, channel 0: 3,000 polygons
// at 512 x 512, 16 samples per pixel) rendered by 1, 2 and 4 pipelines (`--pipelines`): stages A
// and B, each pipeline's raster engine on its own worker thread, the merging video stage. The
// speed-up is the 1-pipeline case's time over the N-pipeline case's, in the same run; the images
// are identical (verif/stress/test_rendering_pipelines.cpp). Counters: polygons per second, the
// load balance (max / mean polygons per pipeline). Also one image on 1 and 2 threads (strips; the
// quadtree: its colour worker).
#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include "generator/image_generator.hpp"
#include "scene/scene_loader.hpp"

namespace cig {
namespace {

const char* const kEngines[] = {"segment", "quadtree"};

void channel(benchmark::State& state) {
  static const Scene scene = load_scene(std::string(CIG_SOURCE_DIR) + "/scenes/airfield.json");
  static const ImageGenerator pipeline(scene);
  const char* engine = kEngines[state.range(0)];
  const int pipelines = int(state.range(1));
  double polygons = 0, balance = 1;
  for (auto _ : state) {
    const std::vector<ChannelOutput> out = pipeline.render(5, {0}, engine, {}, 1, pipelines);
    polygons = out[0].report["geometry"]["polygons_out"].get<double>();
    if (pipelines > 1) balance = out[0].report["pipelines"]["load_balance"].get<double>();
    benchmark::DoNotOptimize(out[0].out.image.rgb.data());
  }
  state.SetLabel(engine);
  state.counters["polygons/s"] = benchmark::Counter(polygons, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["load_balance"] = balance;
}
BENCHMARK(channel)
    ->ArgNames({"engine", "pipelines"})
    ->ArgsProduct({{0, 1}, {1, 2, 4}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// One image on 1 or 2 threads (`render --threads N` with one channel: the engine splits the image
// into strips where it can; the segment processor's video channel shares its lines; the quadtree
// engine moves its pixel processor's colour work to a second worker and resolves in strips; same
// bits, and for the quadtree the same cycle counts).
void strips(benchmark::State& state) {
  static const Scene scene = load_scene(std::string(CIG_SOURCE_DIR) + "/scenes/airfield.json");
  static const ImageGenerator pipeline(scene);
  const char* engine = kEngines[state.range(0)];
  for (auto _ : state) {
    const std::vector<ChannelOutput> out = pipeline.render(5, {0}, engine, {}, int(state.range(1)), 1);
    benchmark::DoNotOptimize(out[0].out.image.rgb.data());
  }
  state.SetLabel(engine);
}
BENCHMARK(strips)
    ->ArgNames({"engine", "threads"})
    ->ArgsProduct({{0, 1}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace cig

BENCHMARK_MAIN();
