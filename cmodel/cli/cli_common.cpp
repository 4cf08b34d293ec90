#include "cli/cli_common.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "common/provenance.hpp"
#include "hls/formatter/records.hpp"
#include "hls/segment/frame_memory.hpp"
#include "hls/segment/overload.hpp"

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

std::string report_text(const nlohmann::ordered_json& report) {
  nlohmann::ordered_json with;
  with["provenance"] = provenance_json();
  for (auto it = report.begin(); it != report.end(); ++it)
    if (it.key() != "provenance") with[it.key()] = it.value();
  return with.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

std::string drop_warning(const nlohmann::ordered_json& engine_report, const std::string& image) {
  if (!engine_report.contains("dropped")) return "";
  const nlohmann::ordered_json& d = engine_report["dropped"];
  const long overload = d.value("polygons_overload", 0L), frame_full = d.value("polygons_frame_memory_full", 0L),
             segment_full = d.value("segments_segment_memory_full", 0L);
  if (overload == 0 && frame_full == 0 && segment_full == 0) return "";
  std::string text = "cig: warning: " + image + ": the " + engine_report.value("engine", std::string("engine")) +
                     " engine's memories were full:";
  if (overload)
    text += " " + std::to_string(overload) +
            " polygon(s) dropped by the overload threshold (the segment memory holds " +
            std::to_string(hls::kSegmentBankWords) + " segments a field);";
  if (frame_full)
    text += " " + std::to_string(frame_full) + " polygon(s) did not fit the frame memory (" +
            std::to_string(hls::kFrameBankWords) + " words a bank);";
  if (segment_full) text += " " + std::to_string(segment_full) + " segment(s) did not fit the segment memory;";
  text.back() = '\n';
  return text;
}

}  // namespace cig::cli
