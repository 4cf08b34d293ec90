#include "scene/polyhedron.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>

#include <glm/geometric.hpp>

#include "scene/polygon_checks.hpp"

namespace cig {

namespace {

// One polygon of the object with its vertices as welded ids.
struct MeshPolygon {
  std::int32_t subobject, polygon;
  std::vector<std::uint32_t> ids;
};

struct Mesh {
  std::vector<glm::dvec3> points;  // welded: one per distinct position
  std::vector<MeshPolygon> polygons;
  double size = 0;  // bounding-box diagonal
};

std::string point_text(const glm::dvec3& p) {
  std::ostringstream s;
  s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return s.str();
}

// Vertices at exactly the same position are one vertex of the solid, whichever subobject (or model)
// they come from, so that a box made of separate subobjects or a model with repeated vertices closes.
Mesh weld(const Object& o) {
  Mesh m;
  std::map<std::array<double, 3>, std::uint32_t> id_of;
  glm::dvec3 lo(1e300), hi(-1e300);
  for (std::size_t si = 0; si < o.subobjects.size(); ++si) {
    const Subobject& s = o.subobjects[si];
    std::vector<std::uint32_t> id(s.vertices.size());
    for (std::size_t i = 0; i < s.vertices.size(); ++i) {
      const glm::dvec3& v = s.vertices[i];
      auto [it, added] = id_of.emplace(std::array<double, 3>{v.x, v.y, v.z}, std::uint32_t(m.points.size()));
      if (added) m.points.push_back(v);
      id[i] = it->second;
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
    for (std::size_t pi = 0; pi < s.polygons.size(); ++pi) {
      MeshPolygon mp{std::int32_t(si), std::int32_t(pi), {}};
      for (auto i : s.polygons[pi].indices) mp.ids.push_back(id[i]);
      m.polygons.push_back(std::move(mp));
    }
  }
  m.size = glm::length(hi - lo);
  return m;
}

// Closed and consistently wound: every directed edge once, and its reverse once.
PolyhedronIssue check_closed(const Mesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> edge;
  for (std::size_t k = 0; k < m.polygons.size(); ++k) {
    const auto& ids = m.polygons[k].ids;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const std::uint32_t a = ids[i], b = ids[(i + 1) % ids.size()];
      if (a == b)
        return {"polyhedron has a zero-length edge at " + point_text(m.points[a]) + " (two corners at one position)",
                m.polygons[k].subobject, m.polygons[k].polygon};
      if (!edge.emplace(std::make_pair(a, b), k).second)
        return {"polyhedron is not closed: the edge " + point_text(m.points[a]) + " -> " + point_text(m.points[b]) +
                    " is used twice in the same direction (more than two faces share it, or neighbouring faces wind "
                    "in opposite senses)",
                m.polygons[k].subobject, m.polygons[k].polygon};
    }
  }
  for (const auto& [e, k] : edge)
    if (!edge.count({e.second, e.first}))
      return {"polyhedron is not closed: the edge " + point_text(m.points[e.first]) + " -> " +
                  point_text(m.points[e.second]) +
                  " belongs to no other face (every edge must be shared by exactly two faces, in opposite directions)",
              m.polygons[k].subobject, m.polygons[k].polygon};
  return {};
}

// Six times the signed volume (positive when the faces wind counter-clockwise seen from outside).
double signed_volume6(const Mesh& m) {
  glm::dvec3 c(0);
  for (const auto& p : m.points) c += p / double(m.points.size());
  double v = 0;
  for (const auto& mp : m.polygons)
    for (std::size_t i = 1; i + 1 < mp.ids.size(); ++i)
      v += glm::dot(m.points[mp.ids[0]] - c, glm::cross(m.points[mp.ids[i]] - c, m.points[mp.ids[i + 1]] - c));
  return v;
}

void reverse_polygons(Object& o, Mesh& m) {
  for (auto& s : o.subobjects)
    for (auto& p : s.polygons) {
      std::reverse(p.indices.begin(), p.indices.end());
      if (p.self_lit) std::reverse(p.self_intensity.begin(), p.self_intensity.end());
    }
  for (auto& mp : m.polygons) std::reverse(mp.ids.begin(), mp.ids.end());
  o.hull.reoriented = true;
}

// The plane of one polygon: Newell's normal, through the mean of its vertices.
PolyhedronFace polygon_plane(const Mesh& m, const MeshPolygon& mp) {
  std::vector<glm::dvec3> pts;
  for (auto i : mp.ids) pts.push_back(m.points[i]);
  PolyhedronFace f;
  f.normal = glm::normalize(newell_normal(pts));
  f.offset = 0;
  for (const auto& p : pts) f.offset += glm::dot(f.normal, p) / double(pts.size());
  return f;
}

double worst_distance(const Mesh& m, const MeshPolygon& mp, const PolyhedronFace& f) {
  double worst = 0;
  for (auto i : mp.ids) worst = std::max(worst, std::abs(glm::dot(f.normal, m.points[i]) - f.offset));
  return worst;
}

std::string tolerance_text(double tol) {
  std::ostringstream s;
  s << tol << " m (" << kPolyhedronTolerance << " x the object's size)";
  return s.str();
}

// Groups polygons into face planes (coplanar polygons facing the same way are one face) and checks
// every face is planar within `tol`.
PolyhedronIssue face_planes(const Mesh& m, double tol, Object& o) {
  std::vector<PolyhedronFace> first;  // each face's first polygon's plane: the grouping key
  std::vector<glm::dvec3> area_sum;   // sum of Newell normals (twice the area, oriented)
  std::vector<std::vector<std::size_t>> members;
  std::vector<std::int32_t> face(m.polygons.size());
  for (std::size_t k = 0; k < m.polygons.size(); ++k) {
    const MeshPolygon& mp = m.polygons[k];
    const PolyhedronFace p = polygon_plane(m, mp);
    const double d = worst_distance(m, mp, p);
    if (d > tol)
      return {"polyhedron face is not planar: a vertex lies " + std::to_string(d) +
                  " m from the polygon's plane (tolerance " + tolerance_text(tol) + ")",
              mp.subobject, mp.polygon};
    std::size_t g = 0;
    while (g < first.size() && !(glm::dot(first[g].normal, p.normal) > 0 && worst_distance(m, mp, first[g]) <= tol))
      ++g;
    if (g == first.size()) {
      first.push_back(p);
      area_sum.emplace_back(0);
      members.emplace_back();
    }
    std::vector<glm::dvec3> pts;
    for (auto i : mp.ids) pts.push_back(m.points[i]);
    area_sum[g] += newell_normal(pts);
    members[g].push_back(k);
    face[k] = std::int32_t(g);
  }
  // The merged face's plane: the area-weighted normal, through the mean of its distinct vertices.
  o.hull.faces.clear();
  for (std::size_t g = 0; g < first.size(); ++g) {
    PolyhedronFace f;
    f.normal = glm::normalize(area_sum[g]);
    std::map<std::uint32_t, bool> seen;
    double sum = 0;
    for (auto k : members[g])
      for (auto i : m.polygons[k].ids)
        if (seen.emplace(i, true).second) sum += glm::dot(f.normal, m.points[i]);
    f.offset = sum / double(seen.size());
    for (auto k : members[g]) {
      const double d = worst_distance(m, m.polygons[k], f);
      if (d > tol)
        return {"polyhedron face is not planar: coplanar polygons merged into one face leave a vertex " +
                    std::to_string(d) + " m from its plane (tolerance " + tolerance_text(tol) + ")",
                m.polygons[k].subobject, m.polygons[k].polygon};
    }
    o.hull.faces.push_back(f);
  }
  o.hull.face_of.assign(o.subobjects.size(), {});
  for (std::size_t si = 0; si < o.subobjects.size(); ++si)
    o.hull.face_of[si].assign(o.subobjects[si].polygons.size(), -1);
  for (std::size_t k = 0; k < m.polygons.size(); ++k)
    o.hull.face_of[std::size_t(m.polygons[k].subobject)][std::size_t(m.polygons[k].polygon)] = face[k];
  return {};
}

// A polygon of the object in a message: "polygon 3" (inline), "mesh 'm' face 7" (a model's, its
// face in the file), with "of subobject 1" when the object has several subobjects.
std::string polygon_text(const Object& o, const MeshPolygon& mp) {
  const Subobject& s = o.subobjects[std::size_t(mp.subobject)];
  std::string t =
      s.model.empty() ? "polygon " + std::to_string(mp.polygon) : model_face_place(s, std::size_t(mp.polygon));
  if (o.subobjects.size() > 1)
    t += " of subobject " + std::to_string(mp.subobject) + (s.model.empty() ? "" : " (model '" + s.model + "')");
  return t;
}

// The two polygons meeting at an edge: "polygons 3 and 8" for two inline polygons of a one-subobject
// object, "mesh 'm' face 3 and mesh 'm' face 8" (or with subobjects) otherwise, "two triangles of
// mesh 'm' face 3" when both come from one model face triangulated at load.
std::string polygon_pair_text(const Object& o, const MeshPolygon& a, const MeshPolygon& b) {
  const Subobject& s = o.subobjects[std::size_t(a.subobject)];
  if (o.subobjects.size() == 1 && s.model.empty())
    return "polygons " + std::to_string(a.polygon) + " and " + std::to_string(b.polygon);
  const std::string ta = polygon_text(o, a), tb = polygon_text(o, b);
  if (ta == tb) return "two triangles of " + ta + " (triangulated at load)";
  return ta + " and " + tb;
}

// One end of an edge: "vertex 12 (x, y, z)", the index in the polygon's subobject's "vertices"
// (as "indices" name it); a model's vertices by position only (object coordinates), since the
// file's own vertex numbering does not survive loading.
std::string vertex_text(const Object& o, const MeshPolygon& mp, std::size_t corner, const glm::dvec3& p) {
  const Subobject& s = o.subobjects[std::size_t(mp.subobject)];
  if (!s.model.empty()) return point_text(p);
  return "vertex " + std::to_string(s.polygons[std::size_t(mp.polygon)].indices[corner]) + " " + point_text(p);
}

// How far the polygon's vertices rise above the plane f (0 when none does).
double rise_above(const Mesh& m, const MeshPolygon& mp, const PolyhedronFace& f) {
  double worst = 0;
  for (auto i : mp.ids) worst = std::max(worst, glm::dot(f.normal, m.points[i]) - f.offset);
  return worst;
}

// Convex. First edge by edge: two polygons on different face planes meeting at an edge must fold
// outward, each lying on the inner side of the other's plane (within tol); the first edge that
// turns inward is named, with its two polygons and its ends. "First" is deterministic: the object's
// polygons in order (subobjects in order, then polygon index within a subobject), and within a
// polygon its edges in the order its corners are listed in the input (corner i to corner i + 1, the
// last to the first; as listed even when the mesh was reversed at load). The test is symmetric, so
// the first edge's polygon is the lowest-indexed polygon that has a reflex edge.
// Then globally: every vertex on the inner side of every face plane (or within tol outside it),
// which catches what no single edge shows (pieces apart, a surface wound around twice).
PolyhedronIssue check_convex(const Mesh& m, double tol, const Object& o) {
  auto face_of = [&](const MeshPolygon& mp) {
    return std::size_t(o.hull.face_of[std::size_t(mp.subobject)][std::size_t(mp.polygon)]);
  };
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> edge;  // directed edge -> polygon (closed)
  for (std::size_t k = 0; k < m.polygons.size(); ++k) {
    const auto& ids = m.polygons[k].ids;
    for (std::size_t i = 0; i < ids.size(); ++i) edge.emplace(std::make_pair(ids[i], ids[(i + 1) % ids.size()]), k);
  }
  for (std::size_t k = 0; k < m.polygons.size(); ++k) {
    const MeshPolygon& a = m.polygons[k];
    const std::size_t n = a.ids.size();
    for (std::size_t e = 0; e < n; ++e) {
      // Corners of edge e as listed in the input (mp.ids is reversed when the mesh was).
      const std::size_t c0 = o.hull.reoriented ? n - 1 - e : e;
      const std::size_t c1 = o.hull.reoriented ? (2 * n - 2 - e) % n : (e + 1) % n;
      const std::uint32_t p0 = a.ids[c0], p1 = a.ids[c1];
      // The neighbour holds the edge in the other direction (check_closed made sure it exists).
      const auto it = o.hull.reoriented ? edge.find({p0, p1}) : edge.find({p1, p0});
      if (it == edge.end()) continue;
      const MeshPolygon& b = m.polygons[it->second];
      const std::size_t fa = face_of(a), fb = face_of(b);
      if (fa == fb) continue;  // coplanar polygons of one face: a flat edge
      const PolyhedronFace &pa = o.hull.faces[fa], &pb = o.hull.faces[fb];
      const double rise_b = rise_above(m, b, pa), rise_a = rise_above(m, a, pb);
      if (std::max(rise_a, rise_b) <= tol) continue;
      // The interior dihedral angle of an inward fold: 180 degrees plus the angle between the normals.
      const double turn = std::atan2(glm::length(glm::cross(pa.normal, pb.normal)), glm::dot(pa.normal, pb.normal));
      std::ostringstream angle;
      angle.setf(std::ios::fixed);
      angle.precision(1);
      angle << 180 + turn * 180 / 3.14159265358979323846;
      const bool b_rises = rise_b >= rise_a;
      return {"polyhedron is not convex: the edge from " + vertex_text(o, a, c0, m.points[p0]) + " to " +
                  vertex_text(o, a, c1, m.points[p1]) + " between " + polygon_pair_text(o, a, b) +
                  " turns inward (interior dihedral angle " + angle.str() +
                  " degrees, more than 180: " + polygon_text(o, b_rises ? b : a) + " rises " +
                  std::to_string(b_rises ? rise_b : rise_a) + " m above the plane of " +
                  polygon_text(o, b_rises ? a : b) + ", tolerance " + tolerance_text(tol) + ")",
              a.subobject, a.polygon};
    }
  }
  for (std::size_t k = 0; k < m.polygons.size(); ++k) {
    const MeshPolygon& mp = m.polygons[k];
    const PolyhedronFace& f = o.hull.faces[face_of(mp)];
    for (const auto& p : m.points) {
      const double out = glm::dot(f.normal, p) - f.offset;
      if (out > tol)
        return {"polyhedron is not convex: no edge turns inward, but the vertex " + point_text(p) + " lies " +
                    std::to_string(out) + " m outside the plane of this face (tolerance " + tolerance_text(tol) +
                    "): its polygons do not bound one convex solid (separate pieces, or a surface that winds "
                    "around more than once)",
                mp.subobject, mp.polygon};
    }
  }
  return {};
}

}  // namespace

PolyhedronIssue build_polyhedron(Object& o) {
  Mesh m = weld(o);
  if (m.polygons.size() < 4) return {"a polyhedron needs at least 4 faces", -1, -1};
  const double tol = kPolyhedronTolerance * m.size;
  PolyhedronIssue issue = check_closed(m);
  if (!issue.rule.empty()) return issue;
  const double v6 = signed_volume6(m);
  if (!(std::abs(v6) > 1e-12 * m.size * m.size * m.size)) return {"polyhedron has no volume", -1, -1};
  // A closed, consistently wound mesh winds inward as a whole or not at all: reverse it so that its
  // normals point out (OBJ exporters differ) and its polygons are drawn from outside.
  if (v6 < 0) reverse_polygons(o, m);
  issue = face_planes(m, tol, o);
  if (!issue.rule.empty()) return issue;
  return check_convex(m, tol, o);
}

}  // namespace cig
