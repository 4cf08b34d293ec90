// The X-Plane apt.dat airport file (versions 850 to 1100; FlightGear's Airports/apt.dat.gz is 1000):
// one airport's land runways (row code 100) and lighting objects (row 21: VASI, PAPI, wig-wags),
// read from the plain or gzip-compressed file. Errors name the file, the line and the rule.
#pragma once

#include <string>
#include <vector>

namespace cig {

struct AptRunwayEnd {
  std::string id;  // "11", "29L"
  double lat_deg = 0, lon_deg = 0;
  double displaced_threshold_m = 0, blast_pad_m = 0;
  int markings = 0;         // 0 none, 1 visual, 2 non-precision, 3 precision, 4-5 UK styles
  int approach_lights = 0;  // 0 none, 1 ALSF-I, 2 ALSF-II, 3 Calvert, 4 Calvert II/III, 5 SSALR, ... 12 RAIL
  int touchdown_zone_lights = 0, reil = 0;
};

struct AptRunway {
  double width_m = 0;
  int surface = 0, shoulder = 0;
  int centreline_lights = 0, edge_lights = 0;  // edge: 0 none, 1 LIRL, 2 MIRL, 3 HIRL
  AptRunwayEnd ends[2];
  int line = 0;  // where it is in the file, for messages
};

struct AptLightObject {
  double lat_deg = 0, lon_deg = 0;
  int type = 0;  // 1 VASI, 2 PAPI-4L, 3 PAPI-4R, 4 space shuttle PAPI, 5 tri-colour VASI, 6 runway guard
  double heading_deg = 0, glideslope_deg = 0;
  std::string runway;
  int line = 0;
};

struct AptAirport {
  std::string icao, name;
  double elevation_ft = 0;
  std::vector<AptRunway> runways;
  std::vector<AptLightObject> lights;
  // Row 1302 datum_lat / datum_lon (the airport reference point) when the file gives them.
  bool has_datum = false;
  double datum_lat_deg = 0, datum_lon_deg = 0;
  std::size_t rows = 0, rows_skipped = 0;  // the airport's rows; those of kinds not read (taxiways, signs...)
  std::string version;                     // the file's version line's number ("1000")
};

// The airport whose header row (code 1, 16 or 17) names `icao`. Throws InputError (file, line, rule)
// on a malformed row of that airport, an unknown version, or when the airport is not in the file.
AptAirport read_apt_dat(const std::string& file, const std::string& icao);

}  // namespace cig
