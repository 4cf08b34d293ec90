// Clipping of convex polygons against the viewing pyramid in eye coordinates (SPEC B):
// the near plane z >= near and the four sides |x| <= t*z, |y| <= t*z (ViewPyramid,
// manager/channel_view.hpp).
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

#include "common/operation_units.hpp"
#include "manager/channel_view.hpp"  // the viewing pyramid (stage A's view of a channel)
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

// What clipping did on the second processor, in seed 000's units (counted as clip.cpp runs it).
struct ClipCount {
  OperationCounts ops;
  std::uint64_t intersections = 0;  // new vertices made on crossing edges
};

// Clips `p` in place against one plane. The intersection on an edge is computed from its inside
// vertex towards its outside vertex, whichever way the polygon runs, so two polygons sharing an
// edge get bit-identical new vertices (no cracks). Returns false when fewer than 3 vertices remain.
// `count` gains what it cost.
bool clip_polygon(ClipPolygon& p, const ClipPlane& plane, ClipCount& count);
bool clip_polygon(ClipPolygon& p, const ClipPlane& plane);
// Clips against every pyramid plane whose bit is set in `planes`.
bool clip_polygon(ClipPolygon& p, const ViewPyramid& pyramid, std::uint8_t planes, ClipCount& count);
bool clip_polygon(ClipPolygon& p, const ViewPyramid& pyramid, std::uint8_t planes);

}  // namespace cig
