#include "scene/polygon_checks.hpp"

#include <cmath>

#include <glm/geometric.hpp>

namespace cig {

glm::dvec3 newell_normal(const std::vector<glm::dvec3>& v) {
  glm::dvec3 n(0);
  for (std::size_t i = 0; i < v.size(); ++i) {
    const glm::dvec3& a = v[i];
    const glm::dvec3& b = v[(i + 1) % v.size()];
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  return n;
}

double signed_area_2d(const std::vector<glm::dvec2>& v) {
  double a = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const glm::dvec2& p = v[i];
    const glm::dvec2& q = v[(i + 1) % v.size()];
    a += p.x * q.y - q.x * p.y;
  }
  return 0.5 * a;
}

namespace {

// Shared convexity test on a polygon already expressed in 2D: every corner turns the same way
// (collinear corners allowed) and the turns add up to one full revolution (rejects stars).
std::string convexity_2d(const std::vector<glm::dvec2>& p) {
  const std::size_t n = p.size();
  double area = signed_area_2d(p);
  double diameter = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) diameter = std::max(diameter, glm::length(p[i] - p[j]));
  if (!(std::abs(area) > 1e-12 * diameter * diameter) || diameter == 0) return "polygon is degenerate (zero area)";
  const double orientation = area > 0 ? 1.0 : -1.0;
  double total_turn = 0;
  for (std::size_t i = 0; i < n; ++i) {
    glm::dvec2 e0 = p[i] - p[(i + n - 1) % n];
    glm::dvec2 e1 = p[(i + 1) % n] - p[i];
    double l0 = glm::length(e0), l1 = glm::length(e1);
    if (l0 <= 1e-12 * diameter || l1 <= 1e-12 * diameter)
      return "polygon repeats vertex " + std::to_string(i) + " (zero-length edge)";
    double cross = orientation * (e0.x * e1.y - e0.y * e1.x) / (l0 * l1);
    double dot = (e0.x * e1.x + e0.y * e1.y) / (l0 * l1);
    if (cross < -kConvexityTolerance)
      return "polygon is not convex (corner at vertex " + std::to_string(i) + " turns the wrong way)";
    total_turn += std::atan2(cross, dot);
  }
  if (std::abs(total_turn - 2 * M_PI) > 1e-6) return "polygon is not simple (its boundary winds more than once)";
  return {};
}

}  // namespace

std::string check_convex_planar(const std::vector<glm::dvec3>& v) {
  if (v.size() < 3) return "polygon has " + std::to_string(v.size()) + " vertices; at least 3 are required";
  glm::dvec3 n = newell_normal(v);
  double len = glm::length(n);
  double diameter = 0;
  glm::dvec3 centroid(0);
  for (const auto& a : v) centroid += a / double(v.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t j = i + 1; j < v.size(); ++j) diameter = std::max(diameter, glm::length(v[i] - v[j]));
  if (!(len > 1e-12 * diameter * diameter) || diameter == 0) {
    // No net area: either every vertex lies on one line (degenerate), or the boundary crosses
    // itself so that its signed areas cancel (a bow-tie), which is an error, not an empty face.
    double spread = 0;
    for (std::size_t i = 1; i + 1 < v.size(); ++i)
      for (std::size_t j = i + 1; j < v.size(); ++j)
        spread = std::max(spread, glm::length(glm::cross(v[i] - v[0], v[j] - v[0])));
    if (diameter > 0 && spread > 1e-6 * diameter * diameter)
      return "polygon is self-intersecting (a bow-tie: its signed areas cancel out)";
    return "polygon is degenerate (zero area)";
  }
  n /= len;
  for (std::size_t i = 0; i < v.size(); ++i) {
    double d = std::abs(glm::dot(v[i] - centroid, n));
    if (d > kPlanarityTolerance * diameter)
      return "polygon is not planar (vertex " + std::to_string(i) + " lies " + std::to_string(d) +
             " from the plane; tolerance " + std::to_string(kPlanarityTolerance * diameter) + ")";
  }
  // Express the polygon in an orthonormal basis of its plane; counter-clockwise around n.
  glm::dvec3 u = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  u = glm::normalize(u - n * glm::dot(u, n));
  glm::dvec3 w = glm::cross(n, u);
  std::vector<glm::dvec2> p;
  p.reserve(v.size());
  for (const auto& a : v) p.emplace_back(glm::dot(a - centroid, u), glm::dot(a - centroid, w));
  return convexity_2d(p);
}

std::string check_convex_2d(const std::vector<glm::dvec2>& v) {
  if (v.size() < 3) return "polygon has " + std::to_string(v.size()) + " vertices; at least 3 are required";
  // Screen polygons may repeat a vertex: clipping a polygon at a plane through one of its corners
  // leaves a zero-length edge that every engine draws as the polygon without it; the check applies
  // to the distinct corners.
  double diameter = 0;
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t j = i + 1; j < v.size(); ++j) diameter = std::max(diameter, glm::length(v[i] - v[j]));
  std::vector<glm::dvec2> corners;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (glm::length(v[i] - v[(i + v.size() - 1) % v.size()]) > 1e-12 * diameter) corners.push_back(v[i]);
  if (corners.size() < 3) return "polygon is degenerate (zero area)";
  return convexity_2d(corners);
}

}  // namespace cig
