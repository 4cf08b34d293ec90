// The ground an airport lies on, as the importer builds it: a height query over the terrain's
// triangles, and runways from apt.dat as polygons that follow the terrain's profile, with their
// markings (ICAO Annex 14 Vol I, 5.2) as decals before the surface in the subobject's priority order.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "import/apt_dat.hpp"
#include "import/fg_scenery.hpp"
#include "scene/scene.hpp"

namespace cig {

// Height of the terrain at a horizontal position: the highest triangle over it (a uniform grid of
// the triangles' boxes, so a query costs the few triangles of one cell).
class GroundHeight {
 public:
  GroundHeight(const std::vector<TerrainTriangle>& triangles, double radius_m, double cell_m = 100);
  // NaN where no triangle lies over (x, y).
  double at(double x, double y) const;
  double at_or(double x, double y, double fallback) const;

 private:
  const std::vector<TerrainTriangle>& tris_;
  double origin_, cell_;
  int n_;
  std::vector<std::uint32_t> start_, items_;  // CSR: cell c's triangles are items_[start_[c] .. start_[c + 1])
};

// Polygons with their colours, each with its own corners (the scene writer shares them by
// millimetre position): one subobject's worth.
struct PolygonSoup {
  std::vector<glm::dvec3> vertices;
  std::vector<std::vector<std::uint32_t>> polygons;
  std::vector<Rgb> colours;
  void add(const std::vector<glm::dvec3>& corners, const Rgb& colour);
};

// A runway's frame: end 0 at `a`, +s along the runway to end 1, +t to the right of +s.
struct RunwayFrame {
  glm::dvec2 a{0}, b{0}, along{0, 1}, right{1, 0};
  double length = 0, width = 0;
  RunwayFrame(const glm::dvec2& end0, const glm::dvec2& end1, double width_m);
  glm::dvec2 at(double s, double t) const { return a + s * along + t * right; }
  double heading_deg() const;  // true heading from end 0 to end 1, clockwise from north
};

struct RunwayPolygons {
  PolygonSoup markings, surface;
  std::size_t marking_polygons = 0;
  double lift_m = 0;                         // the surface's height above the highest terrain under it
  std::vector<double> station_s, station_z;  // the profile: surface height along the centreline
  double z_at(double s) const;
};

// The runway from end 0's blast pad to end 1's, in pieces between profile stations (each piece
// planar: level across, straight along), lifted above the terrain, with the markings its ends'
// codes call for (threshold, designation, centreline, aiming point, touchdown zone, side stripes).
RunwayPolygons build_runway(const AptRunway& rw, const RunwayFrame& f, const GroundHeight& ground, double fallback_z);

}  // namespace cig
