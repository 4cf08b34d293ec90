// `cig import flightgear`: a cig scene from FlightGear's data for an airport (docs/flightgear.md):
// the terrain of the scenery tiles within a radius (BTG, through SimGear), the objects the tiles'
// .stg files place (AC3D models through the scene's model loader), the airport's runways from
// apt.dat as polygons with their markings as decals, and its light points laid out from apt.dat's
// lighting codes (import/airport_lights.hpp). Everything is placed in an east-north-up frame at the
// airport reference point. The scene carries channels and an observer path, an ILS approach, so it
// renders as written.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace cig {

enum class TimeOfDay { day, dusk, night };

struct FlightgearImportOptions {
  std::string icao;
  std::string fg_root;     // the data folder: Airports/apt.dat.gz, Scenery/{Terrain,Objects,Models}
  std::string scene_file;  // where the scene will be written: model paths are made relative to its folder
  double radius_m = 20000;
  double terrain_cell_m = 2000;  // terrain is cut into square objects of this size (culling units)
  std::string approach;          // runway end ("11"); "": the longest runway's end with the most approach lights
  TimeOfDay time = TimeOfDay::dusk;
  double glide_slope_deg = 3;
  double from_nm = 10, to_nm = 0;  // the approach from this distance to the glide path's ground point
  double speed_kt = 140;
  double frame_rate = 50;  // frames per second of the observer path
  int raster = 512;
  bool objects = true;  // the .stg objects (models)
  double max_model_seconds = 60;
};

struct FlightgearImport {
  nlohmann::ordered_json scene;
  nlohmann::ordered_json statistics;  // tiles, triangles, objects, runways, light points by type, times
};

// Throws InputError (file, place, rule) on bad data; the caller writes nothing then.
FlightgearImport import_flightgear(const FlightgearImportOptions& options);

// The statistics as the command prints them.
std::string import_summary_text(const nlohmann::ordered_json& statistics);

}  // namespace cig
