// Load time against input size (issue 34, deliverable 5): a polygon list of 10 k to 1 M triangles
// through load_polygon_list (`cig raster`'s reader), the `cig polys` writer on the same frames,
// and a scene of one OBJ grid of 20 k to 1.3 M triangles through load_scene (JSON, the model
// through assimp in its isolated process, the checks and the priority compiler). The inputs are
// generated into a temporary folder on first use (removed at exit), so a filtered run writes only
// what it needs. Counters: MB/s and polygons/s (or triangles/s), and the process's peak resident
// memory after the case (the sizes run in increasing order, so it is that case's peak), also per
// polygon. tools/bench_load_table.py turns the JSON output into the table and fits the growth
// exponent of time against size, which must stay near 1.
// CIG_BENCH_LOAD_MAX_TRIANGLES=N adds a scene of N triangles (e.g. 10000000: four copies of a
// 2.5 M-triangle OBJ of 90 MB).
#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "bench_inputs.hpp"
#include "frame/screen_frame.hpp"
#include "scene/scene_loader.hpp"

namespace {

namespace fs = std::filesystem;
using cig::ScreenFrame;

// The temporary folder of this run, removed at exit.
struct TempFolder {
  fs::path path = fs::temp_directory_path() / ("cig_bench_load_" + std::to_string(::getpid()));
  TempFolder() { fs::create_directories(path); }
  ~TempFolder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};
const fs::path& temp_folder() {
  static const TempFolder folder;
  return folder.path;
}

double peak_rss_bytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) * 1024.0;  // Linux: kilobytes
}

// n small triangles scattered over the screen, at dyadic coordinates (k/64: short in the list's
// 17-digit text, ~150 bytes a polygon, so 1 M polygons stay within the 256 MiB input limit).
ScreenFrame scattered_triangles(std::size_t n) {
  ScreenFrame f;
  f.raster = 256;
  std::uint64_t state = 1;
  const auto next = [&](int range) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return int((state >> 33) % std::uint64_t(range));
  };
  for (std::size_t i = 0; i < n; ++i) {
    cig::ScreenPolygon p;
    const double x = (next(120) - 60) / 64.0, y = (next(120) - 60) / 64.0, z = 1 + next(100);
    p.vertices = {{x, y, z, 1}, {x + 1 / 64.0, y, z, 1}, {x, y + 1 / 64.0, z, 1}};
    p.colour = {next(4) / 4.0, next(4) / 4.0, next(4) / 4.0};
    f.polygons.push_back(std::move(p));
  }
  return f;
}

void write_text(const fs::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary).write(text.data(), std::streamsize(text.size()));
}

// The polygon list of n triangles, written on first use.
const std::string& list_file(std::size_t n) {
  static std::map<std::size_t, std::string> files;
  auto [it, fresh] = files.emplace(n, (temp_folder() / ("tris" + std::to_string(n) + ".polys.json")).string());
  if (fresh) write_text(it->second, cig::polygon_list_json(scattered_triangles(n)));
  return it->second;
}

// A scene of `copies` subobjects of one model, a k x k grid of squares, each two triangles
// (2 k^2 each), side by side, seen from above. Each copy is read by its own assimp process, which
// may take 4 GiB (IsolationLimits): 2.5 M triangles each at most.
struct SceneFile {
  std::string file;
  double bytes = 0;  // scene and model, the model counted once per copy (each copy reads it)
};
const SceneFile& scene_file(int k, int copies) {
  static std::map<std::pair<int, int>, SceneFile> files;
  auto [it, fresh] = files.emplace(std::make_pair(k, copies), SceneFile{});
  if (!fresh) return it->second;
  const fs::path obj = temp_folder() / ("grid" + std::to_string(k) + ".obj");
  std::string text;
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i <= k; ++i) text += "v " + std::to_string(i) + " " + std::to_string(j) + " 0\n";
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) {
      const long a = long(j) * (k + 1) + i + 1, b = a + 1, c = a + k + 1, d = c + 1;
      text += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(d) + "\nf " +
              std::to_string(a) + " " + std::to_string(d) + " " + std::to_string(c) + "\n";
    }
  write_text(obj, text);
  std::string subobjects;
  for (int c = 0; c < copies; ++c)
    subobjects += std::string(c ? ", " : "") + R"({"model": ")" + obj.filename().string() + R"(", "offset": [)" +
                  std::to_string(c * (k + 1)) + R"(, 0, 0], "up": "z", "colour": [0.5, 0.5, 0.5]})";
  const std::string scene =
      R"({"format": "cig-scene", "version": 1, "raster": 256, "channels": [{"name": "c", "fov": 40}],
 "observer": {"keyframes": [{"frame": 0, "position": [)" +
      std::to_string(k / 2) + ", " + std::to_string(-k / 4) + ", " + std::to_string(k) +
      R"(], "pitch": -60}]},
 "objects": [{"name": "grid", "subobjects": [)" +
      subobjects + "]}]}\n";
  it->second.file = (temp_folder() / ("grid" + std::to_string(k) + ".json")).string();
  write_text(it->second.file, scene);
  it->second.bytes = double(text.size()) * copies + double(scene.size());
  return it->second;
}

void set_counters(benchmark::State& state, double bytes, double items, const char* items_name) {
  using benchmark::Counter;
  const double iterations = double(state.iterations());
  state.counters["MB/s"] = Counter(bytes * iterations / 1e6, Counter::kIsRate);
  state.counters[items_name] = Counter(items * iterations, Counter::kIsRate);
  state.counters["MB"] = bytes / 1e6;
  state.counters["peak_MB"] = peak_rss_bytes() / 1e6;
  state.counters["peak_bytes/item"] = peak_rss_bytes() / items;
}

void register_all() {
  for (std::size_t n : {10'000u, 30'000u, 100'000u, 300'000u, 1'000'000u})
    cig::bench::register_case(
        "load/polygons:" + std::to_string(n),
        [n](benchmark::State& state) {
          const std::string& file = list_file(n);
          std::size_t loaded = 0;
          for (auto _ : state) loaded = cig::load_polygon_list(file).polygons.size();
          if (loaded != n) state.SkipWithError("the list did not load whole");
          set_counters(state, double(fs::file_size(file)), double(n), "polygons/s");
        },
        false);
  for (std::size_t n : {10'000u, 100'000u, 1'000'000u})
    cig::bench::register_case(
        "write/polygons:" + std::to_string(n),
        [n](benchmark::State& state) {
          const ScreenFrame frame = scattered_triangles(n);
          std::size_t bytes = 0;
          for (auto _ : state) bytes = cig::polygon_list_json(frame).size();
          set_counters(state, double(bytes), double(n), "polygons/s");
        },
        false);
  // (k, copies): 2 k^2 copies triangles, 20 k to 1.28 M.
  std::vector<std::pair<int, int>> grids = {{100, 1}, {200, 1}, {400, 1}, {800, 1}};
  if (const char* max = std::getenv("CIG_BENCH_LOAD_MAX_TRIANGLES")) {
    const double n = std::atof(max);
    const int copies = int(std::ceil(n / 2.5e6));
    grids.emplace_back(int(std::lround(std::sqrt(n / copies / 2))), copies);
  }
  for (auto [k, copies] : grids)
    cig::bench::register_case(
        "scene_load/triangles:" + std::to_string(2l * k * k * copies),
        [k = k, copies = copies](benchmark::State& state) {
          const SceneFile& scene = scene_file(k, copies);
          cig::SceneLimits limits;
          limits.max_model_bytes = 4096ll << 20;
          limits.max_model_seconds = 3600;
          try {
            for (auto _ : state) benchmark::DoNotOptimize(cig::load_scene(scene.file, limits).polygon_count());
          } catch (const std::exception& e) {
            state.SkipWithError(e.what());
            return;
          }
          set_counters(state, scene.bytes, 2.0 * k * k * copies, "triangles/s");
        },
        false);
}

}  // namespace

int main(int argc, char** argv) { return cig::bench::run_benchmarks(argc, argv, register_all); }
