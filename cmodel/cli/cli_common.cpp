#include "cli/cli_common.hpp"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "common/provenance.hpp"
#include "hls/formatter/records.hpp"

namespace cig::cli {

namespace {

namespace fs = std::filesystem;

// Whether a file can be created in the existing folder `dir`: a probe file is created and removed
// (permission bits alone do not tell: root may write anywhere except /proc and read-only mounts).
bool can_create_in(const fs::path& dir) {
  const fs::path probe = dir / (".cig-write-probe-" + std::to_string(::getpid()));
  std::ofstream out(probe);
  if (!out) return false;
  out.close();
  std::error_code ec;
  fs::remove(probe, ec);
  return true;
}

// The nearest folder of `p` (itself or an ancestor) that exists.
fs::path nearest_existing(fs::path p) {
  std::error_code ec;
  p = fs::absolute(p, ec);
  while (!p.empty() && !fs::exists(p, ec) && p != p.parent_path()) p = p.parent_path();
  return p;
}

}  // namespace

void EngineArgs::add_to(CLI::App* app, bool required) {
  std::string names;
  for (const auto& n : engine_names()) names += (names.empty() ? "" : ", ") + n;
  auto* option = app->add_option("--engine", engine, "raster engine (" + names + "; `cig engines` lists them)");
  if (required) option->required();
  app->add_option("--engine-opt", opts, "engine setting KEY=VALUE (repeatable; `cig engines` lists each engine's)");
  app->add_flag("--snap", snap, "float engine: snap vertex positions to the formatter's grid first");
  app->add_option("--fan-split", fan_split,
                  "split polygons whose vertex I or 1/Z are not planar into triangle fans: on (default) | off")
      ->check(CLI::IsMember({"on", "off"}));
  // One option per shorthand, its help the key's: "quadtree, quadtree-double: masks=on|off: ...".
  std::map<std::string, std::pair<std::string, std::string>> seen;  // shorthand -> (engines, key's text)
  std::vector<std::string> order;
  for (const EngineInfo& info : engine_infos())
    for (const EngineOptionSpec& spec : info.options) {
      if (spec.shorthand.empty()) continue;
      auto [it, fresh] = seen.try_emplace(spec.shorthand, info.name, spec.key + "=" + spec.range() + ": " + spec.help);
      if (fresh) order.push_back(spec.shorthand);
      else it->second.first += ", " + info.name;
    }
  for (const std::string& shorthand : order)
    app->add_option(shorthand, shorthands[shorthand], seen[shorthand].first + ": " + seen[shorthand].second);
}

EngineOptions EngineArgs::options() const {
  EngineOptions o;
  o.snap = snap;
  o.fan_split = fan_split == "on";
  for (const auto& kv : opts) {
    auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("", "--engine-opt", "'" + kv + "' is not of the form KEY=VALUE");
    o.params[kv.substr(0, eq)] = kv.substr(eq + 1);
  }
  for (const EngineInfo& info : engine_infos())
    for (const EngineOptionSpec& spec : info.options) {
      const auto it = shorthands.find(spec.shorthand);
      if (!spec.shorthand.empty() && it != shorthands.end() && !it->second.empty()) o.params[spec.key] = it->second;
    }
  check_engine_options(engine, o);  // the name and the options before any work, from the engine's table
  return o;
}

namespace {
const std::pair<const char*, HardwareProcessor> kProcessors[] = {{"quadtree", HardwareProcessor::kQuadtree},
                                                                 {"invparam", HardwareProcessor::kInvparam}};
}  // namespace

HardwareProcessor parse_processor(const std::string& text) {
  std::string names;
  for (const auto& p : kProcessors) {
    if (text == p.first) return p.second;
    names += std::string(names.empty() ? "" : ", ") + p.first;
  }
  throw InputError("", "--processor", "'" + text + "' is not one of " + names);
}

const char* processor_name(HardwareProcessor p) {
  for (const auto& k : kProcessors)
    if (k.second == p) return k.first;
  return "?";
}

void check_output_dir(const std::string& dir, const char* option) {
  if (dir.empty()) throw InputError("", option, "the output folder is empty");
  std::error_code ec;
  const fs::path existing = nearest_existing(dir);
  if (!fs::is_directory(existing, ec))
    throw InputError("", option, "'" + existing.string() + "' is not a folder, so '" + dir + "' cannot be created");
  if (!can_create_in(existing))
    throw InputError("", option, "folder '" + existing.string() + "' is not writable (for '" + dir + "')");
}

void check_output_file(const std::string& file, const char* option) {
  if (file.empty()) throw InputError("", option, "the output path is empty");
  std::error_code ec;
  const fs::path p(file);
  if (fs::is_directory(p, ec)) throw InputError("", option, "'" + file + "' is a folder, not a file");
  if (fs::exists(p, ec)) {
    std::ofstream out(file, std::ios::app);  // opened without truncating: nothing is written yet
    if (!out) throw InputError("", option, "'" + file + "' cannot be written");
    return;
  }
  const fs::path parent = p.parent_path().empty() ? fs::path(".") : p.parent_path();
  check_output_dir(parent.string(), option);
}

bool scene_exceeds_ids(const Scene& scene) {
  return scene.polygon_count() > std::size_t(hls::kMaxPolygonIds) ||
         scene.light_point_count() > std::size_t(hls::kMaxPolygonIds);
}

std::vector<int> selected_channels(const Scene& scene, int channel) {
  std::vector<int> channels;
  if (channel >= 0) {
    if (channel >= int(scene.channels.size()))
      throw InputError(scene.file, "--channel",
                       "channel " + std::to_string(channel) + " does not exist (scene has " +
                           std::to_string(scene.channels.size()) + ")");
    channels.push_back(channel);
  } else {
    for (int c = 0; c < int(scene.channels.size()); ++c) channels.push_back(c);
  }
  return channels;
}

std::unique_ptr<RasterEngine> probe_engine(const std::string& engine, const EngineOptions& options, const Scene& scene,
                                           int pipelines) {
  auto probe = make_engine(engine, options);
  probe->check_raster(scene.raster);
  probe->check_scene(scene);
  if (pipelines > 1) probe->check_renders_parts();
  return probe;
}

std::string report_text(const nlohmann::ordered_json& report) {
  nlohmann::ordered_json with;
  with["provenance"] = provenance_json();
  for (auto it = report.begin(); it != report.end(); ++it)
    if (it.key() != "provenance") with[it.key()] = it.value();
  return with.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

// "the segment engine's memories were full: 3 polygon(s) dropped by ...; 2 segment(s) ...", a
// clause per cause with its nonzero counts, in the engine's order.
std::string drop_warning(const nlohmann::ordered_json& engine_report, const std::string& image) {
  if (!engine_report.contains("dropped")) return "";
  const std::string engine = engine_report.value("engine", std::string("engine"));
  const std::vector<DropKind> none;
  const auto& kinds = engine_report.contains("engine") ? engine_info(engine).drops : none;
  const nlohmann::ordered_json& dropped = engine_report["dropped"];
  std::string text;
  for (const DropKind::Cause cause : {DropKind::Cause::kMemoryFull, DropKind::Cause::kCannotDraw}) {
    std::string counts;
    for (const DropKind& k : kinds) {
      const long n = dropped.value(k.key, 0L);
      if (k.cause == cause && n != 0) counts += (counts.empty() ? " " : "; ") + std::to_string(n) + " " + k.what;
    }
    if (counts.empty()) continue;
    text += (text.empty() ? "" : "; ") +
            ("the " + engine + " engine" +
             (cause == DropKind::Cause::kMemoryFull ? "'s memories were full:" : " cannot draw all of its input:") +
             counts);
  }
  for (auto it = dropped.begin(); it != dropped.end(); ++it)  // a count the engine does not describe
    if (std::none_of(kinds.begin(), kinds.end(), [&](const DropKind& k) { return k.key == it.key(); }) &&
        it.value() != 0)
      text += (text.empty() ? "the " + engine + " engine dropped: " : "; ") + it.key() + " " + it.value().dump();
  return text.empty() ? "" : "cig: warning: " + image + ": " + text + "\n";
}

}  // namespace cig::cli
