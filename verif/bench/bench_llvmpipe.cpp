// The peer in the benchmark (issue 14): every cig raster engine against Mesa's llvmpipe (OSMesa,
// llvmpipe_renderer.hpp) on the same screen polygon lists, one thread each, alternating in one
// process: cases `<list>/<engine>` and `<list>/llvmpipe`, registered list by list.
//   * airfield_fFcC: frames 0..4, channels 0..2 of scenes/airfield.json (stages A and B not timed);
//   * depthD: depth complexity D = 2, 10, 20, 40 (after tools/make_depth_complexity.py);
//   * trisK: K = 1k, 10k, 60k small random triangles.
// The generated lists list nearer polygons first, so that their priority order (which the segment
// and quadtree engines trust) agrees with depth (which the float reference and llvmpipe use).
// Time: CPU time of the whole process (MeasureProcessCPUTime), so that a helper thread Mesa might
// start is charged too; LP_NUM_THREADS=0 keeps llvmpipe's rasteriser on the calling thread.
// Threads (deliverable 3): on a few lists each engine also renders with EngineOptions::threads = 2,
// case `<list>/<engine>@2`; tools/bench_table.py reports the wall-time speed-up over the same
// engine's one-thread case of the same run (both cases measure wall time too).
// Curves (issue 34, `bench_llvmpipe --curves`, tools/bench.sh --curves): instead of the table's
// cases, cost against one size at a time, the others as in the table (512 lines, 16 samples per
// pixel), cases `curve/<axis>/<value>/<renderer>` (curve_lists below).
// Samples per pixel: the engines' setting spp; llvmpipe draws S N x S N and box-filters S x S for
// spp = S^2 (1: N x N, 4: 2N, 16: 4N, 64: 8N). A case an engine cannot take fails with its reason:
// "n/a: ..." when the engine does not take the setting, "refused: ..." when it refuses the list.
// Counters: psnr_vs_float (dB against the float engine's image; 99 when identical), pixels_off
// (pixels with a channel off by more than 2 LSB), polygons, dropped (polygons the segment engine's
// overload protection or full frame memory dropped). tools/bench.sh turns the JSON output into
// verif/bench/RESULTS.md (the cig / llvmpipe CPU-time ratios).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "bench_inputs.hpp"
#include "common/error.hpp"
#include "engine/engine.hpp"
#include "image/image_compare.hpp"
#include "llvmpipe_renderer.hpp"
#include "registry/engine_registry.hpp"

namespace cig::bench {
namespace {

const char* const kEngines[] = {"float", "segment", "segment-double", "quadtree", "quadtree-double"};
constexpr int kRaster = 512;
// The lists also rendered on two workers, and that case's suffix.
const char* const kThreadLists[] = {"airfield_f0c0", "airfield_f0c1", "depth10", "depth40", "tris10k"};
constexpr int kThreads = 2;

// Uniform numbers that are the same with every standard library: mt19937_64's sequence is fixed by
// the standard, std::uniform_real_distribution's mapping is not.
class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  double uniform(double lo, double hi) { return lo + (hi - lo) * double(engine_() >> 11) * 0x1p-53; }

 private:
  std::mt19937_64 engine_;
};

using Point = glm::dvec2;

// Sutherland-Hodgman against the sides of [-1, 1]^2: polygon lists come clipped to the screen.
std::vector<Point> clip_to_screen(std::vector<Point> pts) {
  for (int axis = 0; axis < 2; ++axis)
    for (double sign : {-1.0, 1.0}) {
      std::vector<Point> out;
      for (std::size_t k = 0; k < pts.size(); ++k) {
        const Point a = pts[k], b = pts[(k + 1) % pts.size()];
        const double da = sign * a[axis] - 1.0, db = sign * b[axis] - 1.0;  // inside when <= 0
        if (da <= 0) out.push_back(a);
        if ((da <= 0) != (db <= 0)) out.push_back(a + (da / (da - db)) * (b - a));
      }
      pts = std::move(out);
      if (pts.empty()) return pts;
    }
  for (Point& p : pts) p = glm::clamp(p, Point(-1.0), Point(1.0));
  return pts;
}

ScreenFrame empty_list(double fog_start, double fog_end) {
  ScreenFrame f;
  f.raster = kRaster;
  f.fog.colour = {0.5, 0.5, 0.55};
  f.fog.start = fog_start;
  f.fog.end = fog_end;
  f.background = {0.05, 0.05, 0.1};
  return f;
}

// A rotated rectangle at depth z, clipped, its intensity a plane in its own coordinates (a flat
// face lit at a slant); false when it lies off the screen.
bool add_rectangle(ScreenFrame& f, Random& rng, double z, double& area) {
  const double w = rng.uniform(0.15, 0.6), h = rng.uniform(0.15, 0.6);
  const Point c(rng.uniform(-1.1, 1.1), rng.uniform(-1.1, 1.1));
  const double angle = rng.uniform(0, M_PI), ca = std::cos(angle), sa = std::sin(angle);
  std::vector<Point> corners;
  for (const Point& uv : {Point(-w, -h), Point(w, -h), Point(w, h), Point(-w, h)})
    corners.push_back(c + Point(uv.x * ca - uv.y * sa, uv.x * sa + uv.y * ca));
  const double i0 = rng.uniform(0.3, 0.6), iu = rng.uniform(0, 0.2), iv = rng.uniform(0, 0.2);
  const std::vector<Point> pts = clip_to_screen(corners);
  if (pts.size() < 3) return false;
  ScreenPolygon p;
  for (const Point& q : pts) {
    const Point d = q - c;
    const double u = (d.x * ca + d.y * sa) / (2 * w) + 0.5, v = (-d.x * sa + d.y * ca) / (2 * h) + 0.5;
    p.vertices.push_back({q.x, q.y, z, i0 + iu * u + iv * v});
  }
  p.colour = {rng.uniform(0.1, 1), rng.uniform(0.1, 1), rng.uniform(0.1, 1)};
  f.polygons.push_back(p);
  area += 4 * w * h;  // unclipped: slabs overfill the screen a little at its border
  return true;
}

// Depth complexity `slabs` (tools/make_depth_complexity.py's idea with larger rectangles): slabs
// nearest first, each of rectangles whose areas add up to one screen, each polygon behind the one
// before (depth order = list order), a full-screen quad at the back.
ScreenFrame depth_complexity_list(int slabs, std::uint64_t seed) {
  ScreenFrame f = empty_list(30, 200);
  Random rng(seed);
  const double gap = 150.0 / slabs;  // the back stays at about the same depth for every D
  double z = 10;
  for (int slab = 0; slab < slabs; ++slab) {
    for (double area = 0; area < 4.0;)
      if (add_rectangle(f, rng, z, area)) z += 0.01;
    z += gap;
  }
  ScreenPolygon back;
  back.colour = {0.2, 0.2, 0.25};
  for (const Point& q : {Point(-1, -1), Point(1, -1), Point(1, 1), Point(-1, 1)})
    back.vertices.push_back({q.x, q.y, z, 0.5});
  f.polygons.push_back(back);
  return f;
}

// `count` small triangles (circumradius 2 to 6 pixels) spread over the screen, each at its own
// depth, listed nearest first; Gouraud intensity a plane, so that a triangle the screen's edge cuts
// into a quadrilateral stays planar (the engines would split it).
ScreenFrame small_triangles_list(int count, std::uint64_t seed) {
  ScreenFrame f = empty_list(100, 1000);
  Random rng(seed);
  std::vector<std::pair<double, ScreenPolygon>> tris;
  while (int(tris.size()) < count) {
    const Point c(rng.uniform(-1, 1), rng.uniform(-1, 1));
    const double r = rng.uniform(2, 6) * 2.0 / kRaster, a0 = rng.uniform(0, 2 * M_PI), z = rng.uniform(5, 500);
    std::vector<Point> corners;
    for (int k = 0; k < 3; ++k) {
      const double a = a0 + 2 * M_PI * k / 3 + rng.uniform(-0.4, 0.4), rk = r * rng.uniform(0.5, 1);
      corners.push_back(c + rk * Point(std::cos(a), std::sin(a)));
    }
    const double i0 = rng.uniform(0.4, 0.8);
    const Point slope = Point(rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2)) / r;  // I in [0, 1]
    ScreenPolygon p;
    for (const Point& q : clip_to_screen(corners)) p.vertices.push_back({q.x, q.y, z, i0 + glm::dot(slope, q - c)});
    p.colour = {rng.uniform(0.1, 1), rng.uniform(0.1, 1), rng.uniform(0.1, 1)};
    if (p.vertices.size() >= 3) tris.emplace_back(z, std::move(p));
  }
  std::stable_sort(tris.begin(), tris.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (auto& t : tris) f.polygons.push_back(std::move(t.second));
  return f;
}

struct List {
  std::string name;
  std::function<ScreenFrame()> build;
  int spp = 16;  // samples per pixel: the engines' setting spp, llvmpipe's supersampling
};

std::vector<List> all_lists() {
  std::vector<List> lists;
  for (int frame = 0; frame <= 4; ++frame)
    for (int channel = 0; channel <= 2; ++channel)
      lists.push_back({"airfield_f" + std::to_string(frame) + "c" + std::to_string(channel),
                       [=] { return airfield_frame(frame, channel); }});
  for (int d : {2, 10, 20, 40})
    lists.push_back({"depth" + std::to_string(d), [=] { return depth_complexity_list(d, 14000 + d); }});
  for (int k : {1, 10, 60})
    lists.push_back({"tris" + std::to_string(k) + "k", [=] { return small_triangles_list(k * 1000, 14100 + k); }});
  return lists;
}

// The curve family: polygon count (small triangles, 1k to 1M by factors of 4; an engine refuses
// what is beyond its capacities), raster size (the table's airfield_f0c1 list drawn at 128 to 1024
// lines), samples per pixel (the same list at 512 lines, 1 to 64) and depth complexity (2 to 40).
// The lists that are also table lists are built with the table's seeds, so they are the same.
std::vector<List> curve_lists() {
  std::vector<List> lists;
  for (int k : {1, 4, 16, 64, 256, 1000})
    lists.push_back(
        {"curve/polys/" + std::to_string(k * 1000), [=] { return small_triangles_list(k * 1000, 14100 + k); }});
  for (int lines : {128, 256, 512, 1024})
    lists.push_back({"curve/raster/" + std::to_string(lines), [=] {
                       ScreenFrame f = airfield_frame(0, 1);
                       f.raster = lines;  // the geometric processor uses the raster nowhere else
                       return f;
                     }});
  for (int spp : {1, 4, 16, 64})
    lists.push_back({"curve/spp/" + std::to_string(spp), [] { return airfield_frame(0, 1); }, spp});
  for (int d : {2, 5, 10, 20, 40})
    lists.push_back({"curve/depth/" + std::to_string(d), [=] { return depth_complexity_list(d, 14000 + d); }});
  return lists;
}

// The engine's options for a list: its samples per pixel.
EngineOptions list_options(const List& list, int threads) {
  EngineOptions options;
  options.threads = threads;
  options.params["spp"] = std::to_string(list.spp);
  return options;
}

// Built on first use (a filtered run builds only its lists), kept for the other cases of the list.
const ScreenFrame& list_frame(const List& list) {
  static std::map<std::string, ScreenFrame> frames;
  auto it = frames.find(list.name);
  if (it == frames.end()) it = frames.emplace(list.name, list.build()).first;
  return it->second;
}
const Image& float_image(const List& list) {
  static std::map<std::string, Image> images;
  auto it = images.find(list.name);
  if (it == images.end())
    it = images.emplace(list.name, make_engine("float", list_options(list, 1))->render(list_frame(list)).out.image)
             .first;
  return it->second;
}

// The polygons the segment engine dropped: overload protection and full frame memory, wherever
// the report nests its "overload" and "frame_memory" sections.
double dropped_polygons(const nlohmann::ordered_json& report) {
  double n = 0;
  if (!report.is_object()) return n;
  for (auto it = report.begin(); it != report.end(); ++it) {
    if (it.key() == "overload" && it->contains("polygons_dropped")) n += (*it)["polygons_dropped"].get<double>();
    else if (it.key() == "frame_memory" && it->contains("polygons_overflowed"))
      n += (*it)["polygons_overflowed"].get<double>();
    else n += dropped_polygons(*it);
  }
  return n;
}

void set_counters(benchmark::State& state, const List& list, const Image& image, double dropped) {
  const ImageError e = compare_images(image, float_image(list));
  const ScreenFrame& f = list_frame(list);
  state.counters["psnr_vs_float"] = e.psnr();
  state.counters["pixels_off"] = double(e.pixels_over_2lsb);
  state.counters["polygons"] = double(f.polygons.size());
  state.counters["lights"] = double(f.light_points.size());
  state.counters["dropped"] = dropped;
}

// The image for the counters comes from a first, untimed render, which also warms the caches.
void run_engine(benchmark::State& state, const List& list, const std::string& name, int threads) {
  const ScreenFrame& frame = list_frame(list);
  std::unique_ptr<RasterEngine> engine;
  EngineRun first;
  try {
    engine = make_engine(name, list_options(list, threads));
  } catch (const InputError& e) {  // a setting the engine does not take
    state.SkipWithError(("n/a: " + std::string(e.what())).c_str());
    return;
  }
  try {
    first = engine->render(frame);
  } catch (const InputError& e) {  // a list beyond the engine's capacities
    state.SkipWithError(("refused: " + std::string(e.what())).c_str());
    return;
  }
  for (auto _ : state) {
    EngineRun run = engine->render(frame);
    benchmark::DoNotOptimize(run.out.image.rgb.data());
  }
  set_counters(state, list, first.out.image, dropped_polygons(first.report));
}

// One renderer (one GL context) for the process.
LlvmpipeRenderer& llvmpipe() {
  static LlvmpipeRenderer renderer;
  return renderer;
}

// The first render of a list also compiles llvmpipe's shader variants (untimed). spp = S^2: S x S
// samples a pixel.
void run_llvmpipe(benchmark::State& state, const List& list) {
  LlvmpipeRenderer& renderer = llvmpipe();
  const ScreenFrame& frame = list_frame(list);
  const int side = int(std::lround(std::sqrt(double(list.spp))));
  const Image first = renderer.render(frame, side);
  for (auto _ : state) {
    Image image = renderer.render(frame, side);
    benchmark::DoNotOptimize(image.rgb.data());
  }
  set_counters(state, list, first, 0);
}

bool curves = false;  // --curves: the curve family instead of the table's lists

void register_all() {
  benchmark::AddCustomContext("llvmpipe", llvmpipe().version());  // into the JSON output, for RESULTS.md
  static const std::vector<List> lists = curves ? curve_lists() : all_lists();
  for (const List& list : lists) {
    const bool threaded =
        std::find(std::begin(kThreadLists), std::end(kThreadLists), list.name) != std::end(kThreadLists);
    for (const char* engine : kEngines) {
      register_case(list.name + "/" + engine,
                    [&list, name = std::string(engine)](benchmark::State& s) { run_engine(s, list, name, 1); });
      if (threaded)
        register_case(
            list.name + "/" + engine + "@" + std::to_string(kThreads),
            [&list, name = std::string(engine)](benchmark::State& s) { run_engine(s, list, name, kThreads); });
    }
    register_case(list.name + "/llvmpipe", [&list](benchmark::State& s) { run_llvmpipe(s, list); });
  }
}

}  // namespace
}  // namespace cig::bench

int main(int argc, char** argv) {
  // Our own flag, taken out before Google Benchmark reads the others.
  const auto end = std::remove_if(argv + 1, argv + argc, [](const char* a) { return std::string(a) == "--curves"; });
  cig::bench::curves = end != argv + argc;
  argc = int(end - argv);
  setenv("LP_NUM_THREADS", "0", 1);                // llvmpipe rasterises on the calling thread: one thread, like cig
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 0);  // no disk cache (and no cache thread) unless asked
  return cig::bench::run_benchmarks(argc, argv, cig::bench::register_all);
}
