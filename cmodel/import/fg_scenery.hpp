// FlightGear scenery (TerraGear's output, as Debian's flightgear-data-base ships it): the tiles
// ("buckets") around a point, their terrain in BTG files read with SimGear's reader (the field's own
// library: libsimgear-dev), and the objects their .stg files place. Positions come out in a local
// east-north-up frame (import/geodesy.hpp). Only this part of cig links SimGear.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "import/geodesy.hpp"

namespace cig {

// One scenery tile: its folder under Terrain/ and Objects/ ("w030n60/w023n63") and its index.
struct SceneryTile {
  std::string folder;
  long index = 0;
  double lat0_deg = 0, lon0_deg = 0, lat1_deg = 0, lon1_deg = 0;  // its extent
};

// The tiles any part of which lies within radius_m of (lat, lon).
std::vector<SceneryTile> tiles_within(double lat_deg, double lon_deg, double radius_m);

struct TerrainTriangle {
  glm::dvec3 v[3];             // local frame, counter-clockwise seen from above
  std::uint16_t material = 0;  // index into TerrainMesh::materials
};

// A BTG file's light points (TerraGear's own airport lights, e.g. RWY_WHITE_LIGHTS): a check on
// the lights the importer lays out from apt.dat, never drawn.
struct BtgLightPoint {
  std::uint16_t material = 0;
  glm::dvec3 position;
};

struct TerrainMesh {
  std::vector<std::string> materials;  // BTG material names ("Grass", "Ocean", "pa_tiedown"...)
  std::vector<TerrainTriangle> triangles;
  std::vector<BtgLightPoint> lights;
  std::size_t files = 0, ocean_tiles = 0, triangles_read = 0, triangles_outside = 0, degenerate = 0;
  std::uint16_t material(const std::string& name);
};

// Appends a BTG file's triangles (lists, strips and fans) whose centroid lies within radius_m of
// the frame's origin (horizontally) to `mesh`. `airport`: the file is an airport's drop-in
// (OBJECT in the .stg), whose light points are kept. Throws InputError naming the file.
void read_btg(const std::string& file, const LocalFrame& frame, double radius_m, bool airport, TerrainMesh& mesh);

// A tile TerraGear made nothing for is open sea (FlightGear draws such tiles as ocean too): its
// extent in 8 x 8 quads of material Ocean at height 0, those within radius_m appended to `mesh`.
void add_ocean_tile(const SceneryTile& tile, const LocalFrame& frame, double radius_m, TerrainMesh& mesh);

// An object a .stg file places: OBJECT_SHARED (path under the data folder) or OBJECT_STATIC (next
// to the .stg); heading counter-clockwise from north as the .stg gives it.
struct StgObject {
  std::string path;   // resolved file (.ac or .xml), "" when it is missing
  std::string named;  // as the .stg names it
  Geodetic where;     // height: metres above sea level
  double heading_ccw_deg = 0, pitch_deg = 0, roll_deg = 0;
  std::string place;  // "file:line"
};

struct StgFile {
  std::vector<std::string> terrain;   // OBJECT_BASE .btg files (resolved, with .gz when compressed)
  std::vector<std::string> airports;  // OBJECT .btg files
  std::vector<StgObject> objects;
  std::size_t signs = 0, other = 0, missing = 0;  // OBJECT_SIGN rows, other kinds, objects whose file is missing
};

// Reads one .stg file (absent: nothing); `data_root` resolves OBJECT_SHARED paths.
void read_stg(const std::string& file, const std::string& data_root, StgFile& out);

}  // namespace cig
