#include "import/geodesy.hpp"

#include <cmath>

namespace cig {

namespace {
constexpr double kDegToRad = 3.14159265358979323846 / 180;
}

// Geodetic to ECEF on the ellipsoid of semi-major axis a and first eccentricity e^2 = f (2 - f):
// N = a / sqrt(1 - e^2 sin^2 lat) is the prime vertical radius of curvature (TR8350.2 eq. 4-14).
glm::dvec3 geodetic_to_ecef(const Geodetic& g) {
  const double e2 = kWgs84F * (2 - kWgs84F);
  const double lat = g.lat_deg * kDegToRad, lon = g.lon_deg * kDegToRad;
  const double s = std::sin(lat), c = std::cos(lat);
  const double n = kWgs84A / std::sqrt(1 - e2 * s * s);
  return {(n + g.height_m) * c * std::cos(lon), (n + g.height_m) * c * std::sin(lon), (n * (1 - e2) + g.height_m) * s};
}

LocalFrame::LocalFrame(const Geodetic& origin) : origin_(origin), origin_ecef_(geodetic_to_ecef(origin)) {
  const double lat = origin.lat_deg * kDegToRad, lon = origin.lon_deg * kDegToRad;
  const double sl = std::sin(lat), cl = std::cos(lat), so = std::sin(lon), co = std::cos(lon);
  const glm::dvec3 east(-so, co, 0), north(-sl * co, -sl * so, cl), up(cl * co, cl * so, sl);
  // glm is column-major: enu_[c][r]. Row r of the matrix is the r-th axis, so enu_ * d = (e.d, n.d, u.d).
  for (int c = 0; c < 3; ++c) {
    enu_[c][0] = east[c];
    enu_[c][1] = north[c];
    enu_[c][2] = up[c];
  }
}

glm::dvec2 LocalFrame::east_north(double lat_deg, double lon_deg) const {
  const glm::dvec3 p = from_geodetic({lat_deg, lon_deg, 0});
  return {p.x, p.y};
}

double horizontal_distance(const glm::dvec3& a, const glm::dvec3& b) { return std::hypot(a.x - b.x, a.y - b.y); }

}  // namespace cig
