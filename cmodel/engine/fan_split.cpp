#include "engine/fan_split.hpp"

#include <algorithm>
#include <cmath>

namespace cig {

namespace {

// The fan triangle (0, k, k + 1) of largest area, 0 when every one is degenerate.
std::size_t largest_fan_triangle(const std::vector<ScreenVertex>& v) {
  std::size_t best = 0;
  double best_area = 0;
  for (std::size_t k = 1; k + 1 < v.size(); ++k) {
    const double a =
        std::abs((v[k].xs - v[0].xs) * (v[k + 1].ys - v[0].ys) - (v[k].ys - v[0].ys) * (v[k + 1].xs - v[0].xs));
    if (a > best_area) {
      best_area = a;
      best = k;
    }
  }
  return best;
}

// Largest residual of attribute `value` at the vertices against its plane through triangle
// (0, k, k + 1).
template <class Value>
double plane_residual(const std::vector<ScreenVertex>& v, std::size_t k, Value&& value) {
  const double ux = v[k].xs - v[0].xs, uy = v[k].ys - v[0].ys;
  const double wx = v[k + 1].xs - v[0].xs, wy = v[k + 1].ys - v[0].ys;
  const double du = value(v[k]) - value(v[0]), dw = value(v[k + 1]) - value(v[0]);
  const double det = ux * wy - uy * wx;
  const double a = (du * wy - dw * uy) / det, b = (dw * ux - du * wx) / det;
  double worst = 0;
  for (const ScreenVertex& p : v)
    worst = std::max(worst, std::abs(value(v[0]) + a * (p.xs - v[0].xs) + b * (p.ys - v[0].ys) - value(p)));
  return worst;
}

}  // namespace

bool attributes_planar(const ScreenPolygon& p) {
  const auto& v = p.vertices;
  if (v.size() <= 3) return true;
  const std::size_t k = largest_fan_triangle(v);
  if (k == 0) return true;  // no area: covers nothing, nothing to interpolate
  double w_max = 0;
  for (const ScreenVertex& q : v) w_max = std::max(w_max, 1.0 / q.zs);
  return plane_residual(v, k, [](const ScreenVertex& q) { return q.is; }) <= kPlanarIntensityTolerance &&
         plane_residual(v, k, [](const ScreenVertex& q) { return 1.0 / q.zs; }) <= kPlanarInverseDepthTolerance * w_max;
}

FanSplit split_nonplanar_polygons(const ScreenFrame& frame) {
  FanSplit s;
  std::vector<char> planar(frame.polygons.size());
  for (std::size_t pi = 0; pi < frame.polygons.size(); ++pi) planar[pi] = attributes_planar(frame.polygons[pi]);
  if (std::all_of(planar.begin(), planar.end(), [](char c) { return c != 0; })) return s;
  s.frame.raster = frame.raster;
  s.frame.frame = frame.frame;
  s.frame.channel = frame.channel;
  s.frame.fog = frame.fog;
  s.frame.background = frame.background;
  s.frame.polygons.reserve(frame.polygons.size());
  std::vector<std::int32_t> first(frame.polygons.size() + 1);  // first piece of each input polygon
  for (std::size_t pi = 0; pi < frame.polygons.size(); ++pi) {
    const ScreenPolygon& p = frame.polygons[pi];
    first[pi] = std::int32_t(s.frame.polygons.size());
    if (planar[pi]) {
      s.frame.polygons.push_back(p);
      s.source.push_back(std::int32_t(pi));
      continue;
    }
    ++s.polygons_split;
    s.triangles_added += long(p.vertices.size()) - 3;
    for (std::size_t k = 1; k + 1 < p.vertices.size(); ++k) {
      ScreenPolygon t = p;
      t.vertices = {p.vertices[0], p.vertices[k], p.vertices[k + 1]};
      s.frame.polygons.push_back(std::move(t));
      s.source.push_back(std::int32_t(pi));
    }
  }
  first[frame.polygons.size()] = std::int32_t(s.frame.polygons.size());
  s.frame.light_points = frame.light_points;
  for (ScreenLightPoint& l : s.frame.light_points)
    if (l.priority >= 0 && std::size_t(l.priority) <= frame.polygons.size())
      l.priority = first[std::size_t(l.priority)];
  return s;
}

void map_ids_to_source(IdBuffer& ids, const std::vector<std::int32_t>& source) {
  for (std::int32_t& id : ids.id)
    if (id >= 0 && std::size_t(id) < source.size()) id = source[std::size_t(id)];
}

}  // namespace cig
