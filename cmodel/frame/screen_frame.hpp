// The screen-space polygon list: the interface between the geometric processor (stage B) and
// every raster engine (formatter + segment processor, quadtree raster processor, float
// reference). One ScreenFrame is one channel of one frame. Format on disk: "cig-polys",
// documented in scenes/README.md.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

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
  // Where it came from (the scene's object and its light), -1 when read from a polygon list.
  std::int32_t object = -1, light = -1;
};

// Stage F's input (seed 002, SPEC F): the scene's convex polyhedra in eye space, the geometric
// processor's eye frame (metres; the eye at the origin, x to the right, y down, z along the view
// axis). Face k is the plane n.r = d with the outward unit normal n, so the object's interior is
// n.r < d for every face. The ray through screen point (Xs, Ys) is r(t) = t c with
// c = (Xs tan_half_fov, Ys tan_half_fov, 1): its parameter t is the eye depth Z of the point it
// meets (the projection of stage B, Xs = X / (Z tan_half_fov)).
struct EyeFace {
  double nx = 0, ny = 0, nz = 1, d = 0;
  // The face as drawn: its index in ScreenFrame::polygons (shading and ids come from it), -1 when
  // the geometric processor did not draw it (a back face, or culled, or clipped away whole).
  std::int32_t polygon = -1;
  // Every polygon of ScreenFrame::polygons drawn on this face, `polygon` first: a face merged from
  // several coplanar polygons (a triangulated mesh) is drawn as several; a sample belongs to the
  // one that covers it.
  std::vector<std::int32_t> pieces;
};

struct EyePolyhedron {
  std::vector<EyeFace> faces;  // every face, drawn or not: back faces bound the ray's exit (tau_out)
  std::int32_t object = -1;    // the scene object it comes from
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
  // Stage F only: the projection's tan(fov/2) and the convex polyhedra of the scene that passed the
  // culling (empty for a polygon list and for objects that are not convex polyhedra).
  double tan_half_fov = 1;
  double near = 0;  // the near plane's eye depth (view.near; 0: none): nearer points are not drawn
  std::vector<EyePolyhedron> polyhedra;
  // Whether stage B listed the scene's convex polyhedra here: true for every frame of a scene that
  // has some, even one whose channel sees none of them; false for a polygon list.
  bool lists_polyhedra = false;
};

// A capacity check on a polygon list's counts, called once the text is parsed and the counts are
// known, before any polygon is read: `header` has the list's raster, frame, channel, fog and
// background, no polygons. It throws (InputError) to refuse the list.
using PolygonListCheck = std::function<void(const ScreenFrame& header, std::size_t polygons, std::size_t light_points)>;
ScreenFrame load_polygon_list(const std::string& file, const PolygonListCheck& check = {});
ScreenFrame parse_polygon_list(const std::string& text, const std::string& file, const PolygonListCheck& check = {});
// The polygon list of a parsed document (parse_json_text), for a caller that has parsed it already.
ScreenFrame polygon_list_of_document(const nlohmann::json& doc, const std::string& file,
                                     const PolygonListCheck& check = {});
std::string polygon_list_json(const ScreenFrame& f);  // "cig-polys" text
// One list of a channel's rendering-pipeline lists (seed 000) in order: the polygons one after
// another, each light's priority moved by the polygons before its part. Its polygon indices are
// those RasterEngine::render_parts gives its ids in, so a reference rendering it compares id for id.
ScreenFrame concatenate_parts(const std::vector<ScreenFrame>& parts);

}  // namespace cig
