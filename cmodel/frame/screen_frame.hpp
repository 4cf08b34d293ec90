// The screen-space polygon list: the interface between the geometric processor (stage B) and
// every raster engine (formatter + segment processor, quadtree raster processor, float
// reference). One ScreenFrame is one channel of one frame. Format on disk: "cig-polys",
// documented in scenes/README.md.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace cig {

// Screen coordinates as produced by the geometric processor (SPEC B):
//   Xs in [-1, 1] left to right, Ys in [-1, 1] top to bottom (raster line order),
//   Zs > 0 eye depth in metres, Is in [0, 1] Gouraud intensity.
struct ScreenVertex {
  double xs = 0, ys = 0, zs = 1, is = 1;
};

struct ScreenPolygon {
  std::vector<ScreenVertex> vertices;  // convex, at most kMaxScreenVertices, either winding
  Rgb colour{1, 1, 1};
  bool opaque = true;
  bool protect = false;
  // Where it came from (object, subobject, polygon index), -1 when read from a polygon list.
  std::int32_t object = -1, subobject = -1, polygon = -1;
};

struct ScreenLightPoint {
  double xs = 0, ys = 0, zs = 1;
  double ds = 0;  // diameter in the units of Xs (2 = the screen width)
  Rgb colour{1, 1, 1};
  double intensity = 1;
  // Priority-order position: the light ranks just before polygon `priority` of the list (its own
  // object's first polygon), so nearer objects' surfaces hide it in engines that resolve
  // visibility by priority. 0: above every polygon.
  std::int32_t priority = 0;
};

// Polygons are in priority order: index 0 has the highest priority (nearest). Engines that
// resolve visibility by priority use this order; the float reference uses depth and falls back to
// the order only for exactly equal depths.
struct ScreenFrame {
  int raster = 512;
  int frame = 0, channel = 0;
  Fog fog;
  Rgb background{0, 0, 0};
  std::vector<ScreenPolygon> polygons;
  std::vector<ScreenLightPoint> light_points;
};

ScreenFrame load_polygon_list(const std::string& file);
ScreenFrame parse_polygon_list(const std::string& text, const std::string& file);
std::string polygon_list_json(const ScreenFrame& f);  // "cig-polys" text

}  // namespace cig
