// Clipping of convex polygons against the viewing pyramid in eye coordinates (SPEC B):
// the near plane z >= near and the four sides |x| <= t*z, |y| <= t*z.
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace cig {

struct ClipVertex {
  glm::dvec3 eye;    // eye coordinates
  double intensity;  // Gouraud intensity, interpolated along clipped edges
};

// A fixed-capacity polygon: clipping a convex polygon adds at most one vertex per plane.
struct ClipPolygon {
  ClipVertex v[kMaxScreenVertices];
  int n = 0;
};

// Half-space a*x + b*y + c*z + d >= 0 in eye coordinates.
struct ClipPlane {
  double a, b, c, d;
  double distance(const glm::dvec3& e) const { return a * e.x + b * e.y + c * e.z + d; }
  ClipPlane complement() const { return {-a, -b, -c, -d}; }
};

// The five planes of the viewing pyramid, in clipping order: near, left, right, top, bottom.
// Bit k of an outcode refers to plane k.
struct ViewPyramid {
  ClipPlane plane[kClipPlanes];
  ViewPyramid(double tan_half_fov, double near);
  std::uint8_t outcode(const glm::dvec3& e) const;  // planes the point lies outside of
};

// Clips `p` in place against one plane. The intersection on an edge is computed from its inside
// vertex towards its outside vertex, whichever way the polygon runs, so two polygons sharing an
// edge get bit-identical new vertices (no cracks). Returns false when fewer than 3 vertices remain.
bool clip_polygon(ClipPolygon& p, const ClipPlane& plane);
// Clips against every pyramid plane whose bit is set in `planes`.
bool clip_polygon(ClipPolygon& p, const ViewPyramid& pyramid, std::uint8_t planes);

}  // namespace cig
