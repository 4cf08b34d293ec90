#include "scene/scene.hpp"

#include <cmath>
#include <string>

#include <glm/trigonometric.hpp>

namespace cig {

std::size_t Scene::polygon_count() const {
  std::size_t n = 0;
  for (const auto& o : objects)
    for (const auto& s : o.subobjects) n += s.polygons.size();
  return n;
}

std::size_t Scene::light_point_count() const {
  std::size_t n = 0;
  for (const auto& o : objects) n += o.light_points.size();
  return n;
}

std::string model_face_place(const Subobject& s, std::size_t polygon) {
  const ModelFaceRef& f = s.model_faces[polygon];
  const std::string& name = s.model_meshes[f.mesh];
  return (name.empty() ? "mesh " + std::to_string(f.mesh) : "mesh '" + name + "'") + " face " + std::to_string(f.face);
}

glm::dmat3 body_to_world(double heading_deg, double pitch_deg, double roll_deg) {
  const double h = glm::radians(heading_deg), p = glm::radians(pitch_deg), r = glm::radians(roll_deg);
  // Columns are the images of the body axes. M = Rz(-heading) * Rx(pitch) * Ry(roll).
  const double ch = std::cos(h), sh = std::sin(h), cp = std::cos(p), sp = std::sin(p);
  const double cr = std::cos(r), sr = std::sin(r);
  glm::dmat3 rz(ch, -sh, 0, sh, ch, 0, 0, 0, 1);  // column-major: (x,y)->(x ch + y sh, -x sh + y ch)
  glm::dmat3 rx(1, 0, 0, 0, cp, sp, 0, -sp, cp);  // forward (0,1,0) -> (0, cp, sp)
  glm::dmat3 ry(cr, 0, -sr, 0, 1, 0, sr, 0, cr);  // right (1,0,0) -> (cr, 0, -sr): right wing down
  return rz * rx * ry;
}

Pose observer_pose(const Scene& scene, int frame) {
  const auto& k = scene.keyframes;
  if (frame <= k.front().frame) return k.front().pose;
  if (frame >= k.back().frame) return k.back().pose;
  std::size_t i = 1;
  while (k[i].frame < frame) ++i;
  const Pose& a = k[i - 1].pose;
  const Pose& b = k[i].pose;
  const double t = double(frame - k[i - 1].frame) / double(k[i].frame - k[i - 1].frame);
  auto lerp = [t](double x, double y) { return x + (y - x) * t; };
  double dh = std::remainder(b.heading_deg - a.heading_deg, 360.0);  // shorter arc
  Pose p;
  p.position = a.position + (b.position - a.position) * t;
  p.heading_deg = a.heading_deg + dh * t;
  p.pitch_deg = lerp(a.pitch_deg, b.pitch_deg);
  p.roll_deg = lerp(a.roll_deg, b.roll_deg);
  return p;
}

}  // namespace cig
