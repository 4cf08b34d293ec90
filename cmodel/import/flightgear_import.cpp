#include "import/flightgear_import.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <unordered_map>

#include "common/error.hpp"
#include "import/airport_lights.hpp"
#include "import/airport_surfaces.hpp"
#include "import/apt_dat.hpp"
#include "import/fg_scenery.hpp"
#include "import/geodesy.hpp"
#include "scene/model_loader.hpp"
#include "scene/polygon_checks.hpp"

namespace cig {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

constexpr double kFeet = 0.3048, kNauticalMile = 1852, kKnot = kNauticalMile / 3600;
constexpr double kPi = 3.14159265358979323846;
// Priority classes (scenes/README.md, "layer"): terrain lowest, runways on it, objects above.
constexpr int kTerrainLayer = -2, kRunwayLayer = -1;
// TerraGear's painted lines (lf_*) lie in the pavement's triangles' planes: lifted this much so a
// depth buffer shows them, and put before the pavement in the cell's priority order.
constexpr double kLineLiftM = 0.05;
// Light fixtures stand at least this high above the terrain under them (elevated edge lights are
// 0.3-0.4 m; inset lights end up above the runway surface, which is lifted 0.3 m).
constexpr double kMinLightHeightM = 0.45;
// Glide path intercept: 300 m beyond the threshold gives the 15 m threshold crossing height of a
// 3-degree ILS (ICAO Annex 10 reference datum height, 15 m).
constexpr double kGlidePathOriginM = 300;

double round_mm(double v) { return std::round(v * 1000) / 1000; }
glm::dvec3 round_mm(const glm::dvec3& p) { return {round_mm(p.x), round_mm(p.y), round_mm(p.z)}; }
json point(const glm::dvec3& p) { return json::array({round_mm(p.x), round_mm(p.y), round_mm(p.z)}); }
json colour(const Rgb& c) { return json::array({round_mm(c.r), round_mm(c.g), round_mm(c.b)}); }

double elapsed_ms(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// Colours of TerraGear's materials (FlightGear's Materials/base/materials.xml names), linear RGB.
Rgb material_colour(const std::string& m, bool& known) {
  static const std::map<std::string, Rgb> table = {{"Ocean", {0.04, 0.10, 0.16}},
                                                   {"Lake", {0.05, 0.12, 0.18}},
                                                   {"Pond", {0.05, 0.12, 0.18}},
                                                   {"Reservoir", {0.05, 0.12, 0.18}},
                                                   {"Stream", {0.06, 0.13, 0.18}},
                                                   {"Canal", {0.06, 0.13, 0.18}},
                                                   {"Lagoon", {0.05, 0.13, 0.17}},
                                                   {"Estuary", {0.05, 0.12, 0.16}},
                                                   {"Watercourse", {0.06, 0.13, 0.18}},
                                                   {"Grass", {0.22, 0.30, 0.12}},
                                                   {"Grassland", {0.24, 0.30, 0.14}},
                                                   {"Heath", {0.26, 0.25, 0.14}},
                                                   {"Scrub", {0.22, 0.24, 0.12}},
                                                   {"MixedForest", {0.10, 0.18, 0.08}},
                                                   {"DeciduousForest", {0.12, 0.20, 0.08}},
                                                   {"EvergreenForest", {0.08, 0.15, 0.08}},
                                                   {"Rock", {0.30, 0.28, 0.26}},
                                                   {"Lava", {0.16, 0.15, 0.15}},
                                                   {"Sand", {0.55, 0.50, 0.38}},
                                                   {"Glacier", {0.80, 0.82, 0.85}},
                                                   {"SnowCover", {0.85, 0.86, 0.88}},
                                                   {"Town", {0.36, 0.33, 0.30}},
                                                   {"SubUrban", {0.33, 0.32, 0.27}},
                                                   {"Urban", {0.38, 0.36, 0.33}},
                                                   {"BuiltUpCover", {0.36, 0.33, 0.30}},
                                                   {"Industrial", {0.38, 0.36, 0.34}},
                                                   {"Construction", {0.40, 0.36, 0.30}},
                                                   {"Asphalt", {0.16, 0.16, 0.17}},
                                                   {"Road", {0.16, 0.16, 0.17}},
                                                   {"Freeway", {0.16, 0.16, 0.17}},
                                                   {"Dirt", {0.35, 0.27, 0.18}},
                                                   {"Gravel", {0.40, 0.38, 0.34}},
                                                   {"Airport", {0.26, 0.30, 0.16}},
                                                   {"DryCrop", {0.40, 0.36, 0.20}},
                                                   {"IrrCrop", {0.26, 0.34, 0.14}},
                                                   {"CropGrass", {0.28, 0.34, 0.14}},
                                                   {"Marsh", {0.18, 0.24, 0.14}},
                                                   {"Bog", {0.20, 0.22, 0.14}},
                                                   {"Barren", {0.32, 0.30, 0.27}},
                                                   {"OpenMining", {0.40, 0.36, 0.32}},
                                                   {"GolfCourse", {0.24, 0.34, 0.13}},
                                                   {"NaturalCrop", {0.30, 0.32, 0.16}},
                                                   {"Default", {0.28, 0.28, 0.24}}};
  auto it = table.find(m);
  known = true;
  if (it != table.end()) return it->second;
  if (m.rfind("pa_", 0) == 0) return {0.16, 0.16, 0.17};  // asphalt pavement (its painted textures)
  if (m.rfind("pc_", 0) == 0) return {0.42, 0.42, 0.40};  // concrete pavement
  if (m.rfind("lf_", 0) == 0)
    return m.find("yellow") != std::string::npos ? Rgb{0.80, 0.62, 0.05} : Rgb{0.85, 0.85, 0.85};
  known = false;
  return {0.28, 0.28, 0.24};
}

bool is_line_material(const std::string& m) { return m.rfind("lf_", 0) == 0; }

}  // namespace
}  // namespace cig

namespace cig {
namespace {

// One subobject's vertices, shared by their millimetre position (what the scene file keeps).
struct SharedVertices {
  json vertices = json::array();
  std::map<std::array<long long, 3>, std::uint32_t> index;  // by position in millimetres
  std::uint32_t add(const glm::dvec3& p) {
    const std::array<long long, 3> key{std::llround(p.x * 1000), std::llround(p.y * 1000), std::llround(p.z * 1000)};
    auto [it, fresh] = index.emplace(key, std::uint32_t(vertices.size()));
    if (fresh) vertices.push_back(point(p));
    return it->second;
  }
};

struct TerrainCounts {
  std::size_t cells = 0, triangles = 0, dropped = 0, line_triangles = 0;
  std::map<std::string, std::size_t> by_material;
  std::map<std::string, std::size_t> unknown_materials;
};

// A terrain cell: one subobject per material, TerraGear's painted lines (decals) first.
json terrain_cell(const std::string& name, const TerrainMesh& mesh, const std::vector<std::uint32_t>& tris,
                  TerrainCounts& counts) {
  std::map<std::uint16_t, std::vector<std::uint32_t>> by_material;
  for (std::uint32_t t : tris) by_material[mesh.triangles[t].material].push_back(t);
  std::vector<std::uint16_t> order;
  for (const auto& kv : by_material)
    if (is_line_material(mesh.materials[kv.first])) order.push_back(kv.first);
  for (const auto& kv : by_material)
    if (!is_line_material(mesh.materials[kv.first])) order.push_back(kv.first);
  json subs = json::array();
  for (std::uint16_t m : order) {
    const std::string& mat = mesh.materials[m];
    const double lift = is_line_material(mat) ? kLineLiftM : 0;
    bool known = true;
    const Rgb c = material_colour(mat, known);
    SharedVertices sv;
    json polys = json::array();
    for (std::uint32_t t : by_material[m]) {
      std::vector<glm::dvec3> v;
      for (const glm::dvec3& p : mesh.triangles[t].v) v.push_back(round_mm(p + glm::dvec3(0, 0, lift)));
      if (!check_convex_planar(v).empty()) {
        ++counts.dropped;
        continue;
      }
      polys.push_back({{"indices", {sv.add(v[0]), sv.add(v[1]), sv.add(v[2])}}});
      ++counts.triangles;
      ++counts.by_material[mat];
      if (lift > 0) ++counts.line_triangles;
      if (!known) ++counts.unknown_materials[mat];
    }
    if (polys.empty()) continue;
    subs.push_back({{"name", mat},
                    {"colour", colour(c)},
                    {"crease_angle", 30},
                    {"vertices", std::move(sv.vertices)},
                    {"polygons", std::move(polys)}});
  }
  if (subs.empty()) return json();
  ++counts.cells;
  return {{"name", name}, {"layer", kTerrainLayer}, {"subobjects", std::move(subs)}};
}

// The terrain cut into square cells of cell_m (by triangle centroid): the scene manager's culling
// units, as a CIG's database pages terrain.
json terrain_objects(const TerrainMesh& mesh, double radius_m, double cell_m, TerrainCounts& counts) {
  const int n = int(std::ceil(2 * radius_m / cell_m));
  std::map<std::pair<int, int>, std::vector<std::uint32_t>> cells;
  for (std::uint32_t i = 0; i < mesh.triangles.size(); ++i) {
    const glm::dvec3 g = (mesh.triangles[i].v[0] + mesh.triangles[i].v[1] + mesh.triangles[i].v[2]) / 3.0;
    const int cx = std::clamp(int(std::floor((g.x + radius_m) / cell_m)), 0, n - 1);
    const int cy = std::clamp(int(std::floor((g.y + radius_m) / cell_m)), 0, n - 1);
    cells[{cx, cy}].push_back(i);
  }
  json out = json::array();
  for (const auto& kv : cells) {
    json o = terrain_cell("terrain_" + std::to_string(kv.first.first) + "_" + std::to_string(kv.first.second), mesh,
                          kv.second, counts);
    if (!o.is_null()) out.push_back(std::move(o));
  }
  return out;
}

json soup_subobject(const std::string& name, const PolygonSoup& soup) {
  SharedVertices sv;
  json polys = json::array();
  for (std::size_t i = 0; i < soup.polygons.size(); ++i) {
    json idx = json::array();
    for (std::uint32_t k : soup.polygons[i]) idx.push_back(sv.add(soup.vertices[k]));
    polys.push_back({{"indices", idx}, {"colour", colour(soup.colours[i])}});
  }
  return {{"name", name}, {"crease_angle", 0}, {"vertices", std::move(sv.vertices)}, {"polygons", std::move(polys)}};
}

}  // namespace
}  // namespace cig

namespace cig {
namespace {

// An airport light as a scene light point: the fixture height above the terrain under it.
json light_point(const AirportLight& l, const GroundHeight& ground, double fallback_z) {
  const double z = ground.at_or(l.position.x, l.position.y, fallback_z) + std::max(l.position.z, kMinLightHeightM);
  json j = {{"position", point({l.position.x, l.position.y, z})},
            {"diameter", round_mm(l.diameter_m)},
            {"colour", colour(l.colour)},
            {"intensity", round_mm(l.intensity)}};
  if (l.beam.directional)
    j["beam"] = {{"heading", round_mm(l.beam.heading_deg)},
                 {"elevation", round_mm(l.beam.elevation_deg)},
                 {"horizontal", round_mm(l.beam.horizontal_deg)},
                 {"vertical", round_mm(l.beam.vertical_deg)}};
  if (l.has_below) j["below"] = {{"elevation", l.below_elevation_deg}, {"colour", colour(l.below_colour)}};
  return j;
}

// Light objects: one per runway end and light type, so the scene manager culls them in groups and
// the report names them.
void add_light_objects(const std::vector<AirportLight>& lights, const GroundHeight& ground, double fallback_z,
                       json& objects, std::map<std::string, std::size_t>& by_type) {
  std::map<std::string, json> groups;
  for (const AirportLight& l : lights) {
    const std::string type = to_string(l.type);
    groups["lights_" + l.runway_end + "_" + type].push_back(light_point(l, ground, fallback_z));
    ++by_type[type];
  }
  for (auto& kv : groups) objects.push_back({{"name", kv.first}, {"layer", 0}, {"light_points", std::move(kv.second)}});
}

// The model an .xml wrapper names (<path>), resolved next to it; .ac and other files as they are.
// FlightGear's XML models also animate and select levels of detail: the static model is taken.
std::string model_file(const std::string& file, int depth = 0) {
  if (fs::path(file).extension() != ".xml") return file;
  if (depth > 4) return "";
  std::ifstream in(file);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  const std::size_t a = text.find("<path>"), b = text.find("</path>");
  if (a == std::string::npos || b == std::string::npos || b < a) return "";
  std::string p = text.substr(a + 6, b - a - 6);
  p.erase(0, p.find_first_not_of(" \t\r\n"));
  p.erase(p.find_last_not_of(" \t\r\n") + 1);
  const fs::path resolved = fs::path(file).parent_path() / p;
  return fs::is_regular_file(resolved) ? model_file(resolved.string(), depth + 1) : "";
}

struct ObjectCounts {
  std::size_t placed = 0, outside = 0, missing = 0, refused = 0, distinct_models = 0, polygons = 0;
  std::vector<std::string> refusals;  // the first few, with their reasons
};

// The .stg objects within the radius, each model checked once by the scene's own model loader (a
// model it refuses would stop the scene from loading): refused ones are left out and named.
json stg_objects(const std::vector<StgObject>& placed, const LocalFrame& frame, double radius_m, double seconds,
                 ObjectCounts& counts) {
  std::map<std::string, std::pair<bool, std::size_t>> checked;  // model -> (loads, polygons)
  json out = json::array();
  for (const StgObject& o : placed) {
    const glm::dvec3 p = frame.from_geodetic(o.where);
    if (std::hypot(p.x, p.y) > radius_m) {
      ++counts.outside;
      continue;
    }
    const std::string model = o.path.empty() ? "" : model_file(o.path);
    if (model.empty()) {
      ++counts.missing;
      continue;
    }
    auto it = checked.find(model);
    if (it == checked.end()) {
      std::pair<bool, std::size_t> r{true, 0};
      try {
        ModelOptions mo;
        mo.y_up = true;
        mo.seconds = seconds;
        r.second = load_model(model, mo).faces.size();
      } catch (const InputError& e) {
        r.first = false;
        if (counts.refusals.size() < 8) counts.refusals.push_back(e.what());
      }
      it = checked.emplace(model, r).first;
    }
    if (!it->second.first) {
      ++counts.refused;
      continue;
    }
    ++counts.placed;
    counts.polygons += it->second.second;
    // The .stg's heading is counter-clockwise from north, the scene's clockwise.
    out.push_back({{"name", fs::path(o.named).stem().string()},
                   {"position", point(p)},
                   {"heading", round_mm(-o.heading_ccw_deg)},
                   {"pitch", round_mm(o.pitch_deg)},
                   {"roll", round_mm(o.roll_deg)},
                   {"subobjects", json::array({{{"model", fs::absolute(model).string()}, {"up", "y"}}})}});
  }
  counts.distinct_models = checked.size();
  return out;
}

}  // namespace
}  // namespace cig

namespace cig {
namespace {

struct ApproachEnd {
  std::size_t runway = 0;
  int end = 0;
};

double runway_length(const AptRunway& r, const LocalFrame& frame) {
  return glm::length(frame.east_north(r.ends[1].lat_deg, r.ends[1].lon_deg) -
                     frame.east_north(r.ends[0].lat_deg, r.ends[0].lon_deg));
}

// The named runway end, or the longest runway's end best equipped for an ILS approach (precision
// markings, approach lights, touchdown zone lights).
ApproachEnd choose_approach(const AptAirport& a, const LocalFrame& frame, const std::string& wanted,
                            const std::string& apt_file) {
  std::string ends;
  for (std::size_t r = 0; r < a.runways.size(); ++r)
    for (int k = 0; k < 2; ++k) {
      if (a.runways[r].ends[k].id == wanted) return {r, k};
      ends += (ends.empty() ? "" : ", ") + a.runways[r].ends[k].id;
    }
  if (!wanted.empty())
    throw InputError(apt_file, "airport " + a.icao, "no runway end '" + wanted + "' (it has " + ends + ")");
  std::size_t best = 0;
  for (std::size_t r = 1; r < a.runways.size(); ++r)
    if (runway_length(a.runways[r], frame) > runway_length(a.runways[best], frame)) best = r;
  auto score = [](const AptRunwayEnd& e) {
    return (e.markings == 3 ? 4 : 0) + (e.approach_lights > 0 ? 2 : 0) + e.touchdown_zone_lights;
  };
  const AptRunway& rw = a.runways[best];
  return {best, score(rw.ends[1]) > score(rw.ends[0]) ? 1 : 0};
}

// The observer on the glide path, from `from_nm` to `to_nm` before its ground point, at constant
// speed; keyframes at the ends of a straight line (frames between interpolate exactly).
json approach_keyframes(const FlightgearImportOptions& o, const RunwayFrame& f, const RunwayPolygons& rp,
                        const AptRunway& rw, int end, std::size_t& frames) {
  const double disp = rw.ends[end].displaced_threshold_m;
  const double s_gpi = end == 0 ? disp + kGlidePathOriginM : f.length - disp - kGlidePathOriginM;
  const glm::dvec2 landing = end == 0 ? f.along : -f.along;
  const glm::dvec2 gpi = f.at(s_gpi, 0);
  const double z_gpi = rp.z_at(s_gpi) + 4;  // the pilot's eye some 4 m above the wheels at touchdown
  const double v = o.speed_kt * kKnot, d0 = o.from_nm * kNauticalMile, d1 = o.to_nm * kNauticalMile;
  frames = std::size_t(std::floor((d0 - d1) / v * o.frame_rate + 1e-9)) + 1;
  const double tan_gs = std::tan(o.glide_slope_deg * kPi / 180);
  double heading = std::atan2(landing.x, landing.y) * 180 / kPi;
  if (heading < 0) heading += 360;
  json keys = json::array();
  for (std::size_t frame : {std::size_t(0), frames - 1}) {
    const double d = d0 - double(frame) * v / o.frame_rate;
    const glm::dvec2 h = gpi - d * landing;
    keys.push_back({{"frame", frame},
                    {"position", point({h.x, h.y, z_gpi + d * tan_gs})},
                    {"heading", round_mm(heading)},
                    {"pitch", -o.glide_slope_deg},
                    {"roll", 0}});
    if (frames == 1) break;
  }
  return keys;
}

// Sky, sun and fog by time of day. Dusk: the sun 2 degrees up in the west-south-west, the sky's
// glow; night: a high moon's faint light; day: a high sun. Fog ends where the visibility ends.
void environment(TimeOfDay t, json& scene) {
  Rgb sky;
  glm::dvec3 sun;
  double sun_i, ambient, fog_start, fog_end;
  switch (t) {
    case TimeOfDay::day:
      sky = {0.55, 0.68, 0.85}, sun = {-0.4, -0.6, 0.7}, sun_i = 0.7, ambient = 0.3, fog_start = 2000, fog_end = 40000;
      break;
    case TimeOfDay::night:  // a high moon
      sky = {0.012, 0.014, 0.03}, sun = {0.3, -0.5, 0.8}, sun_i = 0.12, ambient = 0.06, fog_start = 0, fog_end = 30000;
      break;
    default:
      sky = {0.28, 0.24, 0.32}, sun = {-0.92, -0.38, 0.035}, sun_i = 0.35, ambient = 0.22, fog_start = 1000,
      fog_end = 30000;
      break;
  }
  scene["lighting"] = {{"sun_direction", point(sun)}, {"sun_intensity", sun_i}, {"ambient", ambient}};
  scene["fog"] = {{"colour", colour(sky)}, {"start", fog_start}, {"end", fog_end}};
  scene["background"] = colour(sky);
  scene["view"]["range"] = fog_end;
}

const char* time_name(TimeOfDay t) { return t == TimeOfDay::day ? "day" : t == TimeOfDay::night ? "night" : "dusk"; }

}  // namespace
}  // namespace cig

namespace cig {
namespace {

struct Sources {
  TerrainMesh terrain;
  StgFile stg;
  std::vector<std::string> tiles;
  std::vector<SceneryTile> ocean;  // tiles without scenery: open sea
};

// The tiles' .stg files (Terrain/ and Objects/), their terrain and airport BTGs.
Sources read_scenery(const std::string& root, const AptAirport& a, const Geodetic& arp, const LocalFrame& frame,
                     double radius_m) {
  Sources s;
  const fs::path terrain = fs::path(root) / "Scenery" / "Terrain", objects = fs::path(root) / "Scenery" / "Objects";
  for (const SceneryTile& t : tiles_within(arp.lat_deg, arp.lon_deg, radius_m)) {
    const std::string name = std::to_string(t.index) + ".stg";
    const std::size_t before = s.stg.terrain.size() + s.stg.airports.size();
    read_stg((terrain / t.folder / name).string(), root, s.stg);
    read_stg((objects / t.folder / name).string(), root, s.stg);
    if (s.stg.terrain.size() + s.stg.airports.size() > before)
      s.tiles.push_back(t.folder + "/" + std::to_string(t.index));
    else s.ocean.push_back(t);
  }
  if (s.tiles.empty())
    throw InputError(
        (terrain).string(), "",
        "no scenery tiles around " + a.icao + " (fetch them: tools/fetch_flightgear.sh, see docs/flightgear.md)");
  for (const std::string& f : s.stg.terrain) read_btg(f, frame, radius_m, false, s.terrain);
  for (const std::string& f : s.stg.airports) read_btg(f, frame, radius_m, true, s.terrain);
  for (const SceneryTile& t : s.ocean) add_ocean_tile(t, frame, radius_m, s.terrain);
  return s;
}

Runway light_runway(const AptRunway& rw, const LocalFrame& frame) {
  Runway r;
  r.width_m = rw.width_m;
  r.surface = rw.surface;
  r.centreline_lights = rw.centreline_lights;
  r.edge_lights = rw.edge_lights;
  for (int k = 0; k < 2; ++k) {
    const AptRunwayEnd& e = rw.ends[k];
    r.ends[k].id = e.id;
    r.ends[k].point = frame.east_north(e.lat_deg, e.lon_deg);
    r.ends[k].displaced_threshold_m = e.displaced_threshold_m;
    r.ends[k].blast_pad_m = e.blast_pad_m;
    r.ends[k].markings = e.markings;
    r.ends[k].approach_lights = e.approach_lights;
    r.ends[k].touchdown_zone_lights = e.touchdown_zone_lights;
    r.ends[k].reil = e.reil;
  }
  return r;
}

}  // namespace
}  // namespace cig

namespace cig {
namespace {

// The laid-out lights against TerraGear's own (the airport BTG's light points, made by other code
// from its own apt.dat): per light type, how many have a TerraGear light within kMatchM, and the
// median and largest horizontal distance of those. A check on the layout, in the report.
json terragear_light_check(const std::vector<AirportLight>& lights, const TerrainMesh& mesh) {
  constexpr double kCellM = 10, kMatchM = 5;
  std::map<std::pair<long, long>, std::vector<glm::dvec2>> grid;
  for (const BtgLightPoint& b : mesh.lights)
    grid[{long(std::floor(b.position.x / kCellM)), long(std::floor(b.position.y / kCellM))}].push_back(
        {b.position.x, b.position.y});
  std::map<std::string, std::vector<double>> matched;
  std::map<std::string, std::size_t> total;
  for (const AirportLight& l : lights) {
    const std::string type = to_string(l.type);
    ++total[type];
    const long cx = long(std::floor(l.position.x / kCellM)), cy = long(std::floor(l.position.y / kCellM));
    double best = 1e300;
    for (long y = cy - 1; y <= cy + 1; ++y)
      for (long x = cx - 1; x <= cx + 1; ++x) {
        auto it = grid.find({x, y});
        if (it == grid.end()) continue;
        for (const glm::dvec2& p : it->second)
          best = std::min(best, std::hypot(p.x - l.position.x, p.y - l.position.y));
      }
    if (best <= kMatchM) matched[type].push_back(best);
  }
  json out = {{"terragear_lights", mesh.lights.size()}, {"match_within_m", kMatchM}};
  for (const auto& kv : total) {
    std::vector<double>& d = matched[kv.first];
    std::sort(d.begin(), d.end());
    out["by_type"][kv.first] = {{"lights", kv.second},
                                {"matched", d.size()},
                                {"median_m", d.empty() ? 0.0 : round_mm(d[d.size() / 2])},
                                {"max_m", d.empty() ? 0.0 : round_mm(d.back())}};
  }
  return out;
}

struct AirportParts {
  json runways = json::array();  // statistics per runway
  std::map<std::string, std::size_t> lights_by_type;
  std::size_t light_objects_skipped = 0, marking_polygons = 0, edge_lights_removed = 0;
  json keyframes;
  std::size_t frames = 0;
  std::string approach_end;
  double approach_heading = 0;
  json terragear_check;
};

// Runways (surface and markings), their lights and the light objects (PAPI, VASI), and the approach.
void airport_objects(const FlightgearImportOptions& o, const AptAirport& a, const LocalFrame& frame,
                     const GroundHeight& ground, const TerrainMesh& mesh, const ApproachEnd& approach, json& objects,
                     AirportParts& parts) {
  std::vector<AirportLight> lights;
  for (std::size_t r = 0; r < a.runways.size(); ++r) {
    const AptRunway& rw = a.runways[r];
    const Runway lr = light_runway(rw, frame);
    const RunwayFrame f(lr.ends[0].point, lr.ends[1].point, rw.width_m);
    const RunwayPolygons rp = build_runway(rw, f, ground, 0);
    const std::string name = "runway_" + rw.ends[0].id + "_" + rw.ends[1].id;
    objects.push_back({{"name", name},
                       {"layer", kRunwayLayer},
                       {"subobjects", json::array({soup_subobject("markings", rp.markings),
                                                   soup_subobject("surface", rp.surface)})}});
    parts.marking_polygons += rp.marking_polygons;
    parts.runways.push_back({{"name", rw.ends[0].id + "/" + rw.ends[1].id},
                             {"length_m", round_mm(f.length)},
                             {"width_m", rw.width_m},
                             {"heading_deg", round_mm(f.heading_deg())},
                             {"marking_polygons", rp.marking_polygons},
                             {"surface_polygons", rp.surface.polygons.size()}});
    std::vector<AirportLight> own = runway_lights(lr);
    // Where runways cross, the shorter one's edge rows break on the longer one's pavement.
    for (const AptRunway& other : a.runways)
      if (&other != &rw && runway_length(other, frame) > f.length)
        parts.edge_lights_removed += remove_edge_lights_on(own, light_runway(other, frame));
    lights.insert(lights.end(), own.begin(), own.end());
    if (r == approach.runway) {
      parts.keyframes = approach_keyframes(o, f, rp, rw, approach.end, parts.frames);
      parts.approach_end = rw.ends[approach.end].id;
      parts.approach_heading = approach.end == 0 ? f.heading_deg() : std::fmod(f.heading_deg() + 180, 360);
    }
  }
  for (const AptLightObject& lo : a.lights) {
    LightObject l;
    l.point = frame.east_north(lo.lat_deg, lo.lon_deg);
    l.type = lo.type;
    l.heading_deg = lo.heading_deg;
    l.glideslope_deg = lo.glideslope_deg;
    l.runway_end = lo.runway;
    const std::vector<AirportLight> units = light_object_lights(l);
    if (units.empty()) ++parts.light_objects_skipped;
    for (const AirportLight& u : units) lights.push_back(u);
  }
  add_light_objects(lights, ground, 0, objects, parts.lights_by_type);
  parts.terragear_check = terragear_light_check(lights, mesh);
}

json terrain_statistics(const Sources& s, const TerrainCounts& tc) {
  return {{"files", s.terrain.files},
          {"ocean_tiles", s.terrain.ocean_tiles},
          {"triangles_read", s.terrain.triangles_read},
          {"triangles_outside_radius", s.terrain.triangles_outside},
          {"triangles_degenerate", s.terrain.degenerate + tc.dropped},
          {"triangles", tc.triangles},
          {"painted_line_triangles", tc.line_triangles},
          {"cells", tc.cells},
          {"by_material", tc.by_material},
          {"unknown_materials", tc.unknown_materials}};
}

json object_statistics(const Sources& s, const ObjectCounts& oc) {
  return {{"placed_in_stg", s.stg.objects.size()},
          {"objects", oc.placed},
          {"outside_radius", oc.outside},
          {"model_missing", oc.missing},
          {"model_refused", oc.refused},
          {"distinct_models", oc.distinct_models},
          {"model_faces", oc.polygons},
          {"signs_skipped", s.stg.signs},
          {"refusals", oc.refusals}};
}

}  // namespace

FlightgearImport import_flightgear(const FlightgearImportOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::string apt_file = (fs::path(o.fg_root) / "Airports" / "apt.dat.gz").string();
  if (!fs::is_regular_file(apt_file))
    throw InputError(
        apt_file, "",
        "not found: fetch FlightGear's data with tools/fetch_flightgear.sh (docs/flightgear.md) or name it with --fg-root");
  const AptAirport a = read_apt_dat(apt_file, o.icao);
  const double apt_ms = elapsed_ms(t0);
  Geodetic arp{0, 0, a.elevation_ft * kFeet};
  if (a.has_datum) {
    arp.lat_deg = a.datum_lat_deg, arp.lon_deg = a.datum_lon_deg;
  } else {  // the runway ends' centroid
    for (const AptRunway& r : a.runways)
      for (const AptRunwayEnd& e : r.ends)
        arp.lat_deg += e.lat_deg / double(2 * a.runways.size()),
            arp.lon_deg += e.lon_deg / double(2 * a.runways.size());
  }
  const LocalFrame frame(arp);
  const ApproachEnd approach = choose_approach(a, frame, o.approach, apt_file);
  const Sources src = read_scenery(o.fg_root, a, arp, frame, o.radius_m);
  const double terrain_read_ms = elapsed_ms(t0) - apt_ms;
  const GroundHeight ground(src.terrain.triangles, o.radius_m);
  TerrainCounts tc;
  json objects = terrain_objects(src.terrain, o.radius_m, o.terrain_cell_m, tc);
  AirportParts parts;
  airport_objects(o, a, frame, ground, src.terrain, approach, objects, parts);
  const auto t_obj = std::chrono::steady_clock::now();
  ObjectCounts oc;
  if (o.objects)
    for (json& j : stg_objects(src.stg.objects, frame, o.radius_m, o.max_model_seconds, oc))
      objects.push_back(std::move(j));
  FlightgearImport out;
  json& scene = out.scene;
  scene = {{"format", "cig-scene"}, {"version", 1}};
  scene["name"] = a.icao + " " + a.name + ": ILS approach runway " + parts.approach_end + " at " + time_name(o.time) +
                  " (FlightGear data)";
  scene["raster"] = o.raster;
  // Light points at least 5 grid units wide (0.6 pixel at 512 lines): a CIG's minimum spot size,
  // which keeps a distant runway light on enough samples not to vanish between them.
  scene["view"] = {{"near", 1.0}, {"light_point_min_diameter", 5}};
  scene["channels"] = json::array({{{"name", "left"}, {"yaw", -40}, {"pitch", 0}, {"fov", 40}},
                                   {{"name", "centre"}, {"yaw", 0}, {"pitch", 0}, {"fov", 40}},
                                   {{"name", "right"}, {"yaw", 40}, {"pitch", 0}, {"fov", 40}}});
  environment(o.time, scene);
  scene["observer"] = {{"keyframes", parts.keyframes}};
  scene["objects"] = std::move(objects);
  std::size_t lights = 0;
  for (const auto& kv : parts.lights_by_type) lights += kv.second;
  json& st = out.statistics;
  st["airport"] = {{"icao", a.icao},
                   {"name", a.name},
                   {"elevation_m", round_mm(a.elevation_ft * kFeet)},
                   {"reference_point", {{"lat", arp.lat_deg}, {"lon", arp.lon_deg}}},
                   {"datum_given", a.has_datum}};
  st["radius_km"] = o.radius_m / 1000;
  st["tiles"] = src.tiles;
  st["terrain"] = terrain_statistics(src, tc);
  st["objects"] = object_statistics(src, oc);
  st["runways"] = parts.runways;
  st["marking_polygons"] = parts.marking_polygons;
  st["light_points"] = {{"total", lights},
                        {"by_type", parts.lights_by_type},
                        {"light_objects_skipped", parts.light_objects_skipped},
                        {"edge_lights_removed_at_crossings", parts.edge_lights_removed},
                        {"terragear_check", parts.terragear_check}};
  st["approach"] = {{"runway", parts.approach_end}, {"heading_deg", round_mm(parts.approach_heading)},
                    {"frames", parts.frames},       {"frame_rate", o.frame_rate},
                    {"from_nm", o.from_nm},         {"to_nm", o.to_nm},
                    {"time", time_name(o.time)}};
  st["ms"] = {{"apt_dat", round_mm(apt_ms)},
              {"terrain_read", round_mm(terrain_read_ms)},
              {"objects", round_mm(elapsed_ms(t_obj))},
              {"total", round_mm(elapsed_ms(t0))}};
  return out;
}

}  // namespace cig

namespace cig {

std::string import_summary_text(const json& st) {
  std::ostringstream s;
  const json& t = st["terrain"];
  const json& ob = st["objects"];
  s << "airport     " << st["airport"]["icao"].get<std::string>() << " " << st["airport"]["name"].get<std::string>()
    << ", radius " << st["radius_km"].get<double>() << " km\n";
  s << "tiles       " << st["tiles"].size() << " (" << t["files"].get<std::size_t>() << " BTG files) and "
    << t["ocean_tiles"].get<std::size_t>() << " of open sea\n";
  s << "terrain     " << t["triangles"].get<std::size_t>() << " triangles in " << t["cells"].get<std::size_t>()
    << " cells (" << t["triangles_read"].get<std::size_t>() << " read, "
    << t["triangles_outside_radius"].get<std::size_t>() << " outside the radius, "
    << t["triangles_degenerate"].get<std::size_t>() << " degenerate; " << t["unknown_materials"].size()
    << " unknown materials)\n";
  s << "objects     " << ob["objects"].get<std::size_t>() << " placed (" << ob["distinct_models"].get<std::size_t>()
    << " models, " << ob["model_faces"].get<std::size_t>() << " faces); " << ob["outside_radius"].get<std::size_t>()
    << " outside the radius, " << ob["model_missing"].get<std::size_t>() << " missing, "
    << ob["model_refused"].get<std::size_t>() << " refused, " << ob["signs_skipped"].get<std::size_t>()
    << " signs skipped\n";
  s << "runways     " << st["runways"].size() << ":";
  for (const json& r : st["runways"])
    s << " " << r["name"].get<std::string>() << " (" << r["length_m"].get<double>() << " x "
      << r["width_m"].get<double>() << " m)";
  s << ", " << st["marking_polygons"].get<std::size_t>() << " marking polygons\n";
  s << "lights      " << st["light_points"]["total"].get<std::size_t>() << ":";
  for (const auto& kv : st["light_points"]["by_type"].items())
    s << " " << kv.key() << " " << kv.value().get<std::size_t>();
  s << "; " << st["light_points"]["light_objects_skipped"].get<std::size_t>()
    << " light objects skipped (wig-wags, ...)\n";
  const json& ap = st["approach"];
  s << "approach    runway " << ap["runway"].get<std::string>() << " (heading " << ap["heading_deg"].get<double>()
    << "), " << ap["frames"].get<std::size_t>() << " frames at " << ap["frame_rate"].get<double>() << " Hz from "
    << ap["from_nm"].get<double>() << " NM, " << ap["time"].get<std::string>() << "\n";
  s << "time        " << st["ms"]["total"].get<double>() << " ms (apt.dat " << st["ms"]["apt_dat"].get<double>()
    << ", terrain " << st["ms"]["terrain_read"].get<double>() << ", objects " << st["ms"]["objects"].get<double>()
    << ")\n";
  return s.str();
}

}  // namespace cig
