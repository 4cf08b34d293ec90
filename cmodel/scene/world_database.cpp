#include "scene/world_database.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/trigonometric.hpp>

#include "scene/polygon_checks.hpp"

namespace cig {

double gouraud_intensity(const Lighting& l, const glm::dvec3& n) {
  double i = l.ambient + l.sun_intensity * std::max(0.0, glm::dot(n, l.sun_direction));
  return std::min(1.0, std::max(0.0, i));
}

namespace {

WorldSubobject place_subobject(const Subobject& s, const glm::dmat3& rot, const glm::dvec3& pos,
                               const Lighting& lighting) {
  WorldSubobject w;
  w.vertices.reserve(s.vertices.size());
  for (const auto& v : s.vertices) w.vertices.push_back(rot * v + pos);

  const std::size_t np = s.polygons.size();
  std::vector<glm::dvec3> pts;
  for (const auto& p : s.polygons) {
    pts.clear();
    for (auto i : p.indices) pts.push_back(w.vertices[i]);
    glm::dvec3 n = glm::normalize(newell_normal(pts));
    w.face_normal.push_back(n);
    glm::dvec3 c(0);
    for (const auto& q : pts) c += q / double(pts.size());
    w.face_offset.push_back(glm::dot(n, c));
  }

  // Faces around each vertex, for the averaged vertex normals.
  std::vector<std::vector<std::uint32_t>> faces_at(w.vertices.size());
  for (std::uint32_t f = 0; f < np; ++f)
    for (auto i : s.polygons[f].indices) faces_at[i].push_back(f);

  const double cos_crease = std::cos(glm::radians(s.crease_angle_deg)) - 1e-12;
  w.first_corner.push_back(0);
  for (std::uint32_t f = 0; f < np; ++f) {
    const Polygon& p = s.polygons[f];
    for (std::size_t k = 0; k < p.indices.size(); ++k) {
      if (p.self_lit) {
        w.corner_intensity.push_back(p.self_intensity[k]);
        continue;
      }
      glm::dvec3 sum(0);
      for (auto g : faces_at[p.indices[k]])
        if (glm::dot(w.face_normal[g], w.face_normal[f]) >= cos_crease) sum += w.face_normal[g];
      glm::dvec3 n = glm::length(sum) > 0 ? glm::normalize(sum) : w.face_normal[f];
      w.corner_intensity.push_back(gouraud_intensity(lighting, n));
    }
    w.first_corner.push_back(std::uint32_t(w.corner_intensity.size()));
  }

  glm::dvec3 lo(1e300), hi(-1e300);
  for (const auto& v : w.vertices) {
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  w.centre = 0.5 * (lo + hi);
  for (const auto& v : w.vertices) w.radius = std::max(w.radius, glm::length(v - w.centre));
  w.radius *= 1 + 1e-12;
  return w;
}

// A directional light placed by its object's rotation: the lobe's frame in the world and the
// bounds of its (azimuth, elevation) rectangle as sines and cosines, the transition's sine. A bound
// past the zenith or the nadir, or a half-width of 180 degrees, is one no direction breaks.
WorldLightDirection place_light_direction(const LightPoint& l, std::uint32_t index, const glm::dmat3& rot) {
  WorldLightDirection w;
  w.light = index;
  if (l.beam) {
    const LightBeam& b = *l.beam;
    const glm::dmat3 frame = rot * b.frame;
    w.beam = true;
    w.right = frame[0];
    w.along = frame[1];
    w.up = frame[2];
    w.elevation = glm::radians(b.elevation_deg);
    w.horizontal = glm::radians(b.horizontal_deg);
    w.vertical = glm::radians(b.vertical_deg);
    w.cos_horizontal = b.horizontal_deg >= 180 ? -1.0 : std::cos(w.horizontal);
    const double lo = b.elevation_deg - b.vertical_deg, hi = b.elevation_deg + b.vertical_deg;
    w.sin_lo = lo <= -90 ? -1.0 : std::sin(glm::radians(lo));
    w.cos_lo = lo <= -90 ? 0.0 : std::cos(glm::radians(lo));
    w.sin_hi = hi >= 90 ? 1.0 : std::sin(glm::radians(hi));
    w.cos_hi = hi >= 90 ? 0.0 : std::cos(glm::radians(hi));
  }
  if (l.below) {
    w.below = true;
    w.sin_below = std::sin(glm::radians(l.below->elevation_deg));
    w.below_colour = l.below->colour;
  }
  return w;
}

}  // namespace

WorldDatabase build_world_database(const Scene& scene) {
  WorldDatabase db;
  db.objects.reserve(scene.objects.size());
  for (const auto& o : scene.objects) {
    WorldObject w;
    glm::dmat3 rot = body_to_world(o.pose.heading_deg, o.pose.pitch_deg, o.pose.roll_deg);
    for (const auto& s : o.subobjects) w.subobjects.push_back(place_subobject(s, rot, o.pose.position, scene.lighting));
    for (std::uint32_t i = 0; i < o.light_points.size(); ++i) {
      const LightPoint& l = o.light_points[i];
      w.light_positions.push_back(rot * l.position + o.pose.position);
      if (l.beam || l.below) w.light_directions.push_back(place_light_direction(l, i, rot));
    }
    w.centre = rot * o.sphere_centre + o.pose.position;
    w.radius = o.sphere_radius;
    w.layer = o.layer;
    w.subobjects_by_distance = o.subobjects_by_distance;
    for (const auto& f : o.hull.faces) {
      const glm::dvec3 n = rot * f.normal;
      w.hull_normal.push_back(n);
      w.hull_offset.push_back(f.offset + glm::dot(n, o.pose.position));
    }
    db.has_polyhedra = db.has_polyhedra || o.polyhedron;
    db.objects.push_back(std::move(w));
  }
  return db;
}

}  // namespace cig
