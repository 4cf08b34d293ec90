// WGS-84 geodesy for database import: geodetic latitude, longitude and height to earth-centred
// earth-fixed (ECEF) coordinates, and from those to a local east-north-up frame at a reference point
// (the scene's world axes: x east, y north, z up, metres). The local frame is exact (a rotation and a
// translation of ECEF), so the earth's curvature stays in the terrain: 20 km from the origin the
// ground lies 31 m below the frame's horizontal plane, as an observer there sees it.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace cig {

struct Geodetic {
  double lat_deg = 0, lon_deg = 0;
  double height_m = 0;  // above the WGS-84 ellipsoid
};

// WGS-84 (NIMA TR8350.2): semi-major axis and flattening.
constexpr double kWgs84A = 6378137.0;
constexpr double kWgs84F = 1 / 298.257223563;

glm::dvec3 geodetic_to_ecef(const Geodetic& g);

class LocalFrame {
 public:
  explicit LocalFrame(const Geodetic& origin);
  const Geodetic& origin() const { return origin_; }
  glm::dvec3 from_ecef(const glm::dvec3& p) const { return enu_ * (p - origin_ecef_); }
  glm::dvec3 from_geodetic(const Geodetic& g) const { return from_ecef(geodetic_to_ecef(g)); }
  // Horizontal position of a latitude and longitude (on the ellipsoid): for 2-D layout (runways).
  glm::dvec2 east_north(double lat_deg, double lon_deg) const;

 private:
  Geodetic origin_;
  glm::dvec3 origin_ecef_;
  glm::dmat3 enu_;  // rows: east, north, up unit vectors in ECEF (stored column-major, transposed)
};

// Great-circle-free flat distance: horizontal distance in the local frame of two points' positions.
double horizontal_distance(const glm::dvec3& a, const glm::dvec3& b);

}  // namespace cig
