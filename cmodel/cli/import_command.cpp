#include "cli/import_command.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli/output_plan.hpp"
#include "common/error.hpp"
#include "common/provenance.hpp"
#include "image/image.hpp"
#include "import/flightgear_import.hpp"

namespace cig::cli {

namespace fs = std::filesystem;

std::string default_flightgear_root() {
  if (const char* r = std::getenv("CIG_FLIGHTGEAR_ROOT")) return r;
  fs::path cache;
  if (const char* c = std::getenv("CIG_FLIGHTGEAR_CACHE")) cache = c;
  else if (const char* h = std::getenv("HOME")) cache = fs::path(h) / ".cache" / "cig" / "flightgear";
  if (!cache.empty() && fs::is_directory(cache / "fgdata")) return (cache / "fgdata").string();
  return "/usr/share/games/flightgear";
}

void ImportCommand::add_to(CLI::App& app) {
  sub = app.add_subcommand("import", "make a scene from another simulator's database (flightgear)");
  sub->require_subcommand(1);
  flightgear =
      sub->add_subcommand("flightgear",
                          "a scene from FlightGear's data for an airport: terrain (BTG), objects (.stg, AC3D), "
                          "runways, markings and lights (apt.dat), an ILS approach (docs/flightgear.md)");
  CLI::App* f = flightgear;
  f->add_option("icao", icao, "airport (ICAO code in apt.dat, e.g. BIKF)")->required();
  f->add_option("--out", out_file, "the scene file to write")->required();
  f->add_option("--report", report_file, "write the import statistics as JSON");
  f->add_option("--radius-km", radius_km, "terrain and objects within this distance of the airport (default 20)")
      ->check(CLI::Range(0.5, 200.0));
  f->add_option("--fg-root", fg_root,
                "FlightGear's data folder (default: the fetch script's cache, see docs/flightgear.md)");
  f->add_option("--approach", approach, "runway end to approach (default: the longest runway's best-equipped end)");
  f->add_option("--time", time, "dusk, night or day (default dusk)")->check(CLI::IsMember({"dusk", "night", "day"}));
  f->add_option("--from-nm", from_nm, "start of the approach, NM before touchdown (default 10)")
      ->check(CLI::Range(0.0, 100.0));
  f->add_option("--to-nm", to_nm, "end of the approach, NM before touchdown (default 0)")
      ->check(CLI::Range(0.0, 100.0));
  f->add_option("--speed-kt", speed_kt, "approach speed, knots (default 140)")->check(CLI::Range(10.0, 1000.0));
  f->add_option("--rate", rate, "frames per second of the observer path (default 50)")->check(CLI::Range(0.01, 1000.0));
  f->add_option("--glide-slope", glide_slope, "glide path angle, degrees (default 3)")->check(CLI::Range(0.5, 10.0));
  f->add_option("--cell-m", cell_m, "terrain cell size, m: the scene manager's culling unit (default 2000)")
      ->check(CLI::Range(100.0, 100000.0));
  f->add_option("--raster", raster, "raster size per channel (default 512)")
      ->check(CLI::IsMember({64, 128, 256, 512, 1024, 2048}));
  f->add_flag("--no-objects", no_objects, "leave out the .stg objects (models)");
  f->add_option("--max-model-seconds", max_model_seconds, "time limit of each model's reading (default 60)")
      ->check(CLI::Range(0.1, 3600.0));
}

namespace {

// The scene file may be replaced only when cig import wrote it (its provenance says so).
void check_replaceable(const std::string& file) {
  if (!fs::exists(file)) return;
  std::ifstream in(file);
  std::string head(4096, '\0');
  in.read(&head[0], std::streamsize(head.size()));
  head.resize(std::size_t(in.gcount()));
  if (head.find("\"generator\":\"cig import flightgear\"") == std::string::npos)
    throw InputError(file, "--out",
                     "exists and was not written by cig import flightgear: not replaced (name a new file)");
}

// One top-level field per line and one object per line: a scene of a million numbers stays a file
// a text editor and grep can take. Provenance first, so check_replaceable finds it.
std::string scene_text(const nlohmann::ordered_json& scene) {
  std::string s = "{\"format\":\"cig-scene\",\"version\":1,\n\"provenance\":" + scene.at("provenance").dump();
  for (const auto& kv : scene.items()) {
    if (kv.key() == "format" || kv.key() == "version" || kv.key() == "provenance") continue;
    s += ",\n\"" + kv.key() + "\":";
    if (kv.key() != "objects") {
      s += kv.value().dump();
      continue;
    }
    s += "[";
    for (std::size_t i = 0; i < kv.value().size(); ++i) s += (i ? ",\n" : "\n") + kv.value()[i].dump();
    s += "\n]";
  }
  return s + "}\n";
}

}  // namespace

int ImportCommand::run() {
  if (!(to_nm < from_nm)) throw InputError("", "--to-nm", "must be less than --from-nm");
  OutputPlan plan;
  plan.file(out_file, "--out");
  if (!report_file.empty()) plan.file(report_file, "--report");
  plan.check();
  check_replaceable(out_file);
  FlightgearImportOptions o;
  o.icao = icao;
  o.fg_root = fg_root.empty() ? default_flightgear_root() : fg_root;
  o.scene_file = out_file;
  o.radius_m = radius_km * 1000;
  o.terrain_cell_m = cell_m;
  o.approach = approach;
  o.time = time == "night" ? TimeOfDay::night : time == "day" ? TimeOfDay::day : TimeOfDay::dusk;
  o.glide_slope_deg = glide_slope;
  o.from_nm = from_nm, o.to_nm = to_nm, o.speed_kt = speed_kt, o.frame_rate = rate;
  o.raster = raster;
  o.objects = !no_objects;
  o.max_model_seconds = max_model_seconds;
  FlightgearImport imp = import_flightgear(o);
  nlohmann::ordered_json prov = {{"generator", "cig import flightgear"}};
  const nlohmann::ordered_json run = provenance_json("cig");
  for (const auto& kv : run.items()) prov[kv.key()] = kv.value();
  prov["fg_root"] = o.fg_root;
  imp.scene["provenance"] = prov;
  write_text_file(out_file, scene_text(imp.scene));
  if (!report_file.empty()) write_text_file(report_file, report_text(imp.statistics));
  std::cout << import_summary_text(imp.statistics) << "cig: wrote " << out_file << "\n";
  return 0;
}

}  // namespace cig::cli
