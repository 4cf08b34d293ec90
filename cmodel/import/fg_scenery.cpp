#include "import/fg_scenery.hpp"

#include <simgear/bucket/newbucket.hxx>
#include <simgear/io/sg_binobj.hxx>
#include <simgear/misc/sg_path.hxx>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <glm/geometric.hpp>

#include "common/error.hpp"

namespace cig {

namespace fs = std::filesystem;

std::vector<SceneryTile> tiles_within(double lat_deg, double lon_deg, double radius_m) {
  // Metres per degree on a sphere of the WGS-84 semi-major axis: good to 0.5 %, and the test below
  // only decides which whole tiles to read (each triangle is then kept by its exact distance).
  const double m_per_deg = kWgs84A * 3.14159265358979323846 / 180;
  const double dlat = radius_m / m_per_deg * 1.01;
  const double dlon = std::min(180.0, dlat / std::max(0.01, std::cos(lat_deg * 3.14159265358979323846 / 180)));
  std::vector<SGBucket> buckets;
  sgGetBuckets(SGGeod::fromDeg(lon_deg - dlon, lat_deg - dlat), SGGeod::fromDeg(lon_deg + dlon, lat_deg + dlat),
               buckets);
  std::vector<SceneryTile> out;
  for (const SGBucket& b : buckets) {
    const double w = b.get_width(), h = b.get_height();
    const double cx = b.get_center_lon(), cy = b.get_center_lat();
    // Nearest point of the tile's rectangle to the centre, in degrees; then in metres.
    const double nx = std::clamp(lon_deg, cx - w / 2, cx + w / 2), ny = std::clamp(lat_deg, cy - h / 2, cy + h / 2);
    const double ex = (nx - lon_deg) * m_per_deg * std::cos(lat_deg * 3.14159265358979323846 / 180);
    const double ey = (ny - lat_deg) * m_per_deg;
    if (std::hypot(ex, ey) <= radius_m * 1.01)
      out.push_back({b.gen_base_path(), b.gen_index(), cy - h / 2, cx - w / 2, cy + h / 2, cx + w / 2});
  }
  return out;
}

std::uint16_t TerrainMesh::material(const std::string& name) {
  for (std::size_t i = 0; i < materials.size(); ++i)
    if (materials[i] == name) return std::uint16_t(i);
  if (materials.size() >= 0xffff) throw InputError("", "", "more than 65535 terrain materials");
  materials.push_back(name);
  return std::uint16_t(materials.size() - 1);
}

namespace {

// Keeps a triangle of the BTG's node indices when its centroid lies within the radius; turns it to
// face up (terrain is seen from above; TerraGear winds counter-clockwise seen from outside).
struct TriangleSink {
  const std::vector<glm::dvec3>& local;
  double radius;
  TerrainMesh& mesh;

  void add(int a, int b, int c, std::uint16_t m) {
    const int n = int(local.size());
    ++mesh.triangles_read;
    if (a < 0 || b < 0 || c < 0 || a >= n || b >= n || c >= n)
      throw InputError("", "", "a triangle's vertex index is out of range");
    TerrainTriangle t{{local[std::size_t(a)], local[std::size_t(b)], local[std::size_t(c)]}, m};
    const glm::dvec3 g = (t.v[0] + t.v[1] + t.v[2]) / 3.0;
    if (std::hypot(g.x, g.y) > radius) {
      ++mesh.triangles_outside;
      return;
    }
    const glm::dvec3 normal = glm::cross(t.v[1] - t.v[0], t.v[2] - t.v[0]);
    if (!(glm::length(normal) > 1e-6)) {
      ++mesh.degenerate;
      return;
    }
    if (normal.z < 0) std::swap(t.v[1], t.v[2]);
    mesh.triangles.push_back(t);
  }
};

void add_groups(const group_list& groups, const string_list& materials, int kind, TriangleSink& sink) {
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const int_list& v = groups[g];
    const std::uint16_t m = sink.mesh.material(g < materials.size() ? materials[g] : std::string("Default"));
    if (kind == 0) {
      for (std::size_t i = 0; i + 2 < v.size(); i += 3) sink.add(v[i], v[i + 1], v[i + 2], m);
    } else if (kind == 1) {  // strip: every other triangle winds the other way
      for (std::size_t i = 0; i + 2 < v.size(); ++i)
        i % 2 ? sink.add(v[i + 1], v[i], v[i + 2], m) : sink.add(v[i], v[i + 1], v[i + 2], m);
    } else {  // fan
      for (std::size_t i = 1; i + 1 < v.size(); ++i) sink.add(v[0], v[i], v[i + 1], m);
    }
  }
}

}  // namespace

void read_btg(const std::string& file, const LocalFrame& frame, double radius_m, bool airport, TerrainMesh& mesh) {
  SGBinObject obj;
  if (!obj.read_bin(SGPath(file)))
    throw InputError(file, "", "SimGear's BTG reader could not read it (not a BTG file, or damaged)");
  const SGVec3d c = obj.get_gbs_center();
  std::vector<glm::dvec3> local;
  local.reserve(obj.get_wgs84_nodes().size());
  for (const SGVec3d& p : obj.get_wgs84_nodes())
    local.push_back(frame.from_ecef({c.x() + p.x(), c.y() + p.y(), c.z() + p.z()}));
  TriangleSink sink{local, radius_m, mesh};
  try {
    add_groups(obj.get_tris_v(), obj.get_tri_materials(), 0, sink);
    add_groups(obj.get_strips_v(), obj.get_strip_materials(), 1, sink);
    add_groups(obj.get_fans_v(), obj.get_fan_materials(), 2, sink);
  } catch (const InputError& e) { throw InputError(file, "", e.rule()); }
  if (airport) {
    for (std::size_t g = 0; g < obj.get_pts_v().size(); ++g) {
      const std::uint16_t m = mesh.material(obj.get_pt_materials()[g]);
      for (int i : obj.get_pts_v()[g])
        if (i >= 0 && std::size_t(i) < local.size()) mesh.lights.push_back({m, local[std::size_t(i)]});
    }
  }
  ++mesh.files;
}

void add_ocean_tile(const SceneryTile& tile, const LocalFrame& frame, double radius_m, TerrainMesh& mesh) {
  constexpr int kQuads = 8;
  std::vector<glm::dvec3> local;
  for (int j = 0; j <= kQuads; ++j)
    for (int i = 0; i <= kQuads; ++i)
      local.push_back(frame.from_geodetic({tile.lat0_deg + (tile.lat1_deg - tile.lat0_deg) * j / kQuads,
                                           tile.lon0_deg + (tile.lon1_deg - tile.lon0_deg) * i / kQuads, 0}));
  TriangleSink sink{local, radius_m, mesh};
  const std::uint16_t ocean = mesh.material("Ocean");
  for (int j = 0; j < kQuads; ++j)
    for (int i = 0; i < kQuads; ++i) {
      const int a = j * (kQuads + 1) + i, b = a + 1, c = a + kQuads + 1, d = c + 1;
      sink.add(a, b, d, ocean);
      sink.add(a, d, c, ocean);
    }
  ++mesh.ocean_tiles;
}

namespace {

// A .btg named by a .stg: compressed (name.gz) or not.
std::string btg_file(const fs::path& dir, const std::string& name) {
  const fs::path gz = dir / (name + ".gz");
  if (fs::is_regular_file(gz)) return gz.string();
  return (dir / name).string();
}

// OBJECT_SHARED paths are relative to the data folder; Debian's package keeps the shared models
// under Scenery/Models, where FlightGear finds them through its scenery path.
std::string shared_file(const std::string& root, const std::string& path) {
  for (const fs::path& p : {fs::path(root) / path, fs::path(root) / "Scenery" / path})
    if (fs::is_regular_file(p)) return p.string();
  return "";
}

}  // namespace

void read_stg(const std::string& file, const std::string& data_root, StgFile& out) {
  std::ifstream in(file);
  if (!in) return;
  const fs::path dir = fs::path(file).parent_path();
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::istringstream s(line);
    std::string kind, name;
    if (!(s >> kind) || kind[0] == '#') continue;
    s >> name;
    if (kind == "OBJECT_BASE") {
      out.terrain.push_back(btg_file(dir, name));
    } else if (kind == "OBJECT") {
      out.airports.push_back(btg_file(dir, name));
    } else if (kind == "OBJECT_SHARED" || kind == "OBJECT_STATIC") {
      StgObject o;
      o.named = name;
      o.place = file + ":" + std::to_string(number);
      if (!(s >> o.where.lon_deg >> o.where.lat_deg >> o.where.height_m >> o.heading_ccw_deg))
        throw InputError(file, "line " + std::to_string(number),
                         kind + " needs a path, longitude, latitude, elevation and heading");
      if (!(s >> o.pitch_deg >> o.roll_deg)) o.pitch_deg = o.roll_deg = 0;
      o.path = kind == "OBJECT_SHARED" ? shared_file(data_root, name)
                                       : (fs::is_regular_file(dir / name) ? (dir / name).string() : "");
      if (o.path.empty()) ++out.missing;
      out.objects.push_back(o);
    } else if (kind == "OBJECT_SIGN") {
      ++out.signs;
    } else {
      ++out.other;
    }
  }
}

}  // namespace cig
