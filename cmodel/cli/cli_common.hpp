// Pieces shared by the cig commands: the engine options every command takes, frame ranges, output
// file names.
#pragma once

#include <cctype>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "common/timing.hpp"
#include "engine/engine.hpp"
#include "manager/visibility_unit.hpp"
#include "registry/engine_registry.hpp"
#include "scene/scene.hpp"
#include "scene/scene_loader.hpp"

namespace cig::cli {

// A scene has 1 to 8 channels (scene_loader.cpp): --channel takes 0..7 (range-checked by CLI11).
constexpr int kMaxChannelIndex = 7;

// --engine, --engine-opt, --snap and the shorthands of engine settings (--arch, --masks,
// --start-window: EngineOptionSpec::shorthand, so they follow the engines' tables).
struct EngineArgs {
  std::string engine = "float";
  std::vector<std::string> opts;
  bool snap = false;
  std::string fan_split = "on";
  std::map<std::string, std::string> shorthands;  // shorthand option -> value given

  // `required`: the command compares an engine with the reference, so it must be named.
  void add_to(CLI::App* app, bool required = false);
  EngineOptions options() const;
};

// --max-model-mb, --max-model-seconds: the largest model file a scene may reference, and how long
// assimp may take to read one (scenes/README.md, "Valid ranges").
struct ModelLimitArgs {
  int max_model_mb = int(kDefaultMaxModelBytes >> 20);
  double max_model_seconds = kDefaultMaxModelSeconds;
  std::string priority_cache = default_priority_cache_dir();
  bool modeller_order = false;
  void add_to(CLI::App* app) {
    app->add_option("--priority-cache", priority_cache,
                    "directory of compiled priority trees, by content hash (default ~/.cache/cig/priority; "
                    "none: compile at every load)");
    app->add_flag("--modeller-order", modeller_order,
                  "no priority compiler: every subobject keeps its modeller's polygon order");
    app->add_option("--max-model-mb", max_model_mb, "largest model file read, in MiB (default 64)")
        ->check(CLI::Range(1, 4096));
    app->add_option("--max-model-seconds", max_model_seconds,
                    "time assimp may take to read one model before the file is refused (default 60)")
        ->check(CLI::Range(0.1, 3600.0));
  }
  SceneLimits limits() const {
    SceneLimits l{(long long)max_model_mb << 20, max_model_seconds, {}};
    l.priority.enabled = !modeller_order;
    l.priority.cache_dir = priority_cache == "none" ? "" : priority_cache;
    return l;
  }
};

// --manager-unit: how stage A decides V[i] (manager/visibility_unit.hpp): the hls/manager kernel
// (the default, as stages C-F run theirs) or its double twin.
struct ManagerUnitArgs {
  std::string unit = "kernel";
  void add_to(CLI::App* app) {
    app->add_option("--manager-unit", unit,
                    "stage A's visibility test: kernel (hls/manager, bit-accurate, default) or double (its twin)")
        ->check(CLI::IsMember({"kernel", "double"}));
  }
  VisibilityArith arith() const {
    return unit == visibility_arith_name(VisibilityArith::kDouble) ? VisibilityArith::kDouble
                                                                   : VisibilityArith::kKernel;
  }
};

// The processors that have an architecture model and RTL (`cig arch`, `cig cosim` --processor):
// seed 004's raster processor and seed 002's systolic array.
enum class HardwareProcessor { kQuadtree, kInvparam };
// InputError at --processor for a name that is none of them.
HardwareProcessor parse_processor(const std::string& text);
const char* processor_name(HardwareProcessor p);

// "A:B" (inclusive) or "K".
inline void parse_frames(const std::string& text, int& a, int& b) {
  auto bad = [&] { throw InputError("", "--frames", "'" + text + "' is not of the form A:B (inclusive, A <= B)"); };
  auto colon = text.find(':');
  try {
    std::size_t used = 0;
    if (colon == std::string::npos) {
      a = b = std::stoi(text, &used);
      if (used != text.size()) bad();
    } else {
      a = std::stoi(text.substr(0, colon), &used);
      if (used != colon) bad();
      b = std::stoi(text.substr(colon + 1), &used);
      if (used != text.size() - colon - 1) bad();
    }
  } catch (const std::logic_error&) { bad(); }
  if (a < 0 || b < a) bad();
}

inline std::string frame_name(int frame) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "frame_%04d", frame);
  return buf;
}

inline std::string safe_name(const std::string& s) {
  std::string r;
  for (char c : s) r += (std::isalnum((unsigned char)c) || c == '-' || c == '_') ? c : '_';
  return r;
}

// An output file named by `option`: checked before any work (it is not a folder, it can be written,
// its folder exists or can be created: the writers create it), so that no run ends in an
// unwritable path after the work is done.
void check_output_file(const std::string& file, const char* option);
// An output folder: it exists and is writable, or can be created.
void check_output_dir(const std::string& dir, const char* option);
// A JSON report as text, led by its "provenance" (version, commit, command line, date:
// common/provenance.hpp). Strings that are not UTF-8 (paths) are written with U+FFFD in place of
// their invalid bytes instead of failing after the work is done.
std::string report_text(const nlohmann::ordered_json& report);

// Whether some frame of the scene could hold more polygons or lights than a polygon id counts
// (hls::kMaxPolygonIds): only then must the frames go through stages A and B to be checked.
bool scene_exceeds_ids(const Scene& scene);

// The warning for what an engine left out of one image (its report's "dropped", engine_registry.hpp
// EngineInfo::drops: the segment processor's overload drops and full memories, what stage F cannot
// draw), one line with every nonzero count and what it means; "" when nothing was lost. `image`
// names it ("frame 3 channel 1", a file). Never silent: every command that renders prints it on
// stderr.
std::string drop_warning(const nlohmann::ordered_json& engine_report, const std::string& image);

// The channels a command works on: all, or --channel C (InputError when the scene lacks it).
std::vector<int> selected_channels(const Scene& scene, int channel);

// The engine a command renders the scene with, checked against the scene before any work: its
// raster, its content, and rendering pipelines when pipelines > 1 (InputError).
std::unique_ptr<RasterEngine> probe_engine(const std::string& engine, const EngineOptions& options, const Scene& scene,
                                           int pipelines);

// The frames to process: --frames A:B, --frame K, or frame 0; checked against the path.
inline void frame_range(const std::string& frames_text, int frame_k, bool frame_given, int frame_count,
                        const std::string& scene_file, int& a, int& b) {
  a = b = 0;
  if (!frames_text.empty()) parse_frames(frames_text, a, b);
  else if (frame_k >= 0) a = b = frame_k;
  else if (frame_given) throw InputError("", "--frame", "frame must not be negative");
  const int last = frame_count - 1;
  if (b > last)
    throw InputError(
        scene_file, "observer.keyframes",
        "frame " + std::to_string(b) + " lies outside the observer path (frames 0.." + std::to_string(last) + ")");
}

}  // namespace cig::cli
