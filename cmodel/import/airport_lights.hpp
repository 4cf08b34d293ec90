// An airport's light points from X-Plane apt.dat (version 1000) runway and light-object rows: the
// geometry only (no file reading). A runway (row 100) becomes its edge, threshold, end, centre
// line, touchdown zone, approach and REIL lights at ICAO Annex 14 Vol. I (chapter 5, Appendix 2)
// spacing and colours, with the FAA AC 150/5340-30 layouts for the US approach systems apt.dat
// names; a light object (row 21) becomes its PAPI or VASI units. The rules are named constants
// in airport_lights.cpp, each citing its paragraph.
//
// Local metric frame: x east, y north, metres; z up, metres above the runway surface at that point
// (the caller adds the terrain elevation under each light). Headings are clockwise from north (+y).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace cig {

enum class AirportLightType {
  runway_edge,
  threshold,
  runway_end,
  centreline,
  touchdown_zone,
  approach,
  reil,
  papi,
  vasi
};
const char* to_string(AirportLightType);  // "runway_edge", "threshold", ... (used in reports)

// A light's beam. Directional: the axis points at azimuth heading_deg (clockwise from north) and
// elevation elevation_deg; the intensity is multiplied by f = max(0, 1 - (da/h)^2 - (de/v)^2), da
// and de the eye's azimuth and elevation offsets from the axis, h = horizontal_deg and
// v = vertical_deg the half-widths. Omnidirectional when !directional.
struct AirportLightBeam {
  bool directional = false;
  double heading_deg = 0, elevation_deg = 0, horizontal_deg = 180, vertical_deg = 90;
};

// One light point. A bidirectional fixture (edge, centre line, threshold/end) is two lights at the
// same position, one per direction, since its colour differs by direction.
struct AirportLight {
  AirportLightType type = AirportLightType::runway_edge;
  std::string runway_end;        // the end whose landing direction the light faces ("11", "29")
  glm::dvec3 position{0, 0, 0};  // local x, y; z above the surface
  Rgb colour{1, 1, 1};           // linear [0, 1]
  double intensity = 1;          // [0, 1], relative (high-intensity edge = 1, medium 0.6, low 0.3 ...)
  double diameter_m = 0.3;
  AirportLightBeam beam;
  bool flashing = false;  // sequenced flashers, RAIL, ODALS, REIL (the scene may show them steady)
  // PAPI/VASI: below the elevation angle below_elevation_deg, seen from the light, the eye sees
  // below_colour instead of colour.
  bool has_below = false;
  double below_elevation_deg = 0;
  Rgb below_colour{1, 0, 0};
};

// apt.dat row 100, one end. point: the end's apt.dat point (the runway's physical end, before any
// displacement of the threshold); the other fields are apt.dat's codes.
struct RunwayEnd {
  std::string id;  // "11"
  glm::dvec2 point{0, 0};
  double displaced_threshold_m = 0, blast_pad_m = 0;
  int markings = 0;               // 0 none, 1 visual, 2 non-precision, 3 precision, 4 UK non-precision, 5 UK precision
  int approach_lights = 0;        // 0 none, 1 ALSF-I ... 12 RAIL
  int touchdown_zone_lights = 0;  // 0, 1
  int reil = 0;                   // 0 none, 1 omnidirectional, 2 unidirectional
};

struct Runway {
  double width_m = 45;
  int surface = 1, centreline_lights = 0, edge_lights = 0;  // edge: 0 none, 1 LIRL, 2 MIRL, 3 HIRL
  RunwayEnd ends[2];
};

// apt.dat row 21. type: 1 VASI, 2 PAPI-4L, 3 PAPI-4R, 4 space shuttle PAPI, 5 tri-colour VASI,
// 6 runway guard (wig-wag). heading_deg: the heading of the runway it serves (the landing
// direction); point: the centre of the light units.
struct LightObject {
  glm::dvec2 point{0, 0};
  int type = 0;
  double heading_deg = 0, glideslope_deg = 3;
  std::string runway_end;
};

// Every light of the runway: edge lights, threshold and end lights, centre line lights, then per
// end its touchdown zone lights, approach lighting and REIL. Throws InputError (common/error.hpp) for a runway that has
// no length, a width or displaced thresholds out of range, a non-finite number or a lighting code
// apt.dat 1000 does not define.
std::vector<AirportLight> runway_lights(const Runway& r);

// Removes from `lights` the edge lights that would stand on `other`'s pavement (between its end
// points, within its width), where runways cross: elevated fixtures cannot stand there, and Annex
// 14 5.3.9 lets an intersection break the rows. The caller picks the runway that gives way. Returns
// how many were removed; throws as runway_lights does for a degenerate `other`.
std::size_t remove_edge_lights_on(std::vector<AirportLight>& lights, const Runway& other);

// The PAPI (types 2, 3) or VASI (type 1) units of a light object; empty for the other types (the
// caller counts them as skipped). Throws InputError for a non-finite point or heading, or a glide
// slope outside (0, 10) degrees.
std::vector<AirportLight> light_object_lights(const LightObject& o);

// A PAPI at its ICAO place beside runway end `end` (0 or 1): on the left (PAPI-4L) or right
// (PAPI-4R) of the landing direction, its centre distance_m past the landing threshold and its
// inner unit 15 m outside the runway edge (Annex 14 5.3.5, Figure 5-20). For
// runways whose apt.dat rows give no light object.
LightObject standard_papi(const Runway& r, int end, bool left_side, double distance_m, double glideslope_deg = 3);

}  // namespace cig
