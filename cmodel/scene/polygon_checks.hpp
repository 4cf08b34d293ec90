// Geometric validity of input polygons: every stage downstream assumes convex planar polygons
// (the edge generator splits a boundary into one left and one right chain; the quadtree setup
// describes the polygon as an intersection of half-planes), so the loaders reject anything else.
#pragma once

#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace cig {

// Relative tolerances (documented in scenes/README.md).
// Planarity: every vertex lies within kPlanarityTolerance * diameter of the polygon's plane.
constexpr double kPlanarityTolerance = 1e-4;
// Convexity: a corner may turn the wrong way by at most this angle (radians), which admits
// collinear vertices and rounding noise but not a visible dent.
constexpr double kConvexityTolerance = 1e-6;

// Empty when `v` is a convex planar polygon with non-zero area; otherwise the rule it breaks.
std::string check_convex_planar(const std::vector<glm::dvec3>& v);
// The same in the plane (screen polygons).
std::string check_convex_2d(const std::vector<glm::dvec2>& v);

// Newell's normal (length = twice the area) of a 3D polygon.
glm::dvec3 newell_normal(const std::vector<glm::dvec3>& v);
// Signed area of a 2D polygon (positive when counter-clockwise in a y-up frame).
double signed_area_2d(const std::vector<glm::dvec2>& v);

}  // namespace cig
