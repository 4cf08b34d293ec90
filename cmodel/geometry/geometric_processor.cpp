#include "geometry/geometric_processor.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "common/timing.hpp"
#include "geometry/clip.hpp"
#include "hls/formatter/sample_lattice.hpp"  // the scene sizes light points in formatter grid units

namespace cig {

ScreenVertex project(const glm::dvec3& e, double intensity, double t) {
  ScreenVertex v;
  v.xs = std::clamp(e.x / (t * e.z), -1.0, 1.0);
  v.ys = std::clamp(-e.y / (t * e.z), -1.0, 1.0);
  v.zs = e.z;
  v.is = intensity;
  return v;
}

PriorityWalkCost walk_priority_tree(const std::vector<BspNode>& tree, const WorldSubobject& w, const glm::dvec3& eye,
                                    bool back_to_front, std::vector<std::uint32_t>& order) {
  // Explicit stack of (node, its polygons are due): a partition node is pushed as "rest of the
  // chain, far side, own polygons, near side", so that the near side is popped first.
  const std::size_t start = order.size();
  std::vector<std::pair<std::int32_t, bool>> stack{{0, false}};
  PriorityWalkCost cost;
  auto push = [&](std::int32_t k, bool emit) {
    stack.push_back({k, emit});
    cost.ops.L += 2;  // pushed and, later, popped
  };
  cost.ops.L += 2;
  while (!stack.empty()) {
    const auto [k, emit] = stack.back();
    stack.pop_back();
    const BspNode& node = tree[std::size_t(k)];
    if (emit) {
      for (std::uint32_t p = node.first; p < node.first + node.count; ++p) order.push_back(p);
      cost.ops.L += node.count;
      continue;
    }
    ++cost.nodes;
    cost.ops.L += 5;
    ++cost.ops.C;
    if (node.next >= 0) push(node.next, false);  // the rest of the chain comes after
    if (node.front < 0 && node.back < 0) {       // a run: no plane to test
      push(k, true);
      continue;
    }
    // The eye's side of the node's plane (that of its first polygon): nearer side first.
    ++cost.partitions;
    cost.ops.L += 4;
    cost.ops.M += 3;
    cost.ops.A += 2;
    const bool eye_in_front = glm::dot(w.face_normal[node.first], eye) > w.face_offset[node.first];
    const std::int32_t near_side = eye_in_front ? node.front : node.back;
    const std::int32_t far_side = eye_in_front ? node.back : node.front;
    if (far_side >= 0) push(far_side, false);
    push(k, true);
    if (near_side >= 0) push(near_side, false);
  }
  // Farthest first is the same order reversed (a painter's order).
  if (back_to_front) std::reverse(order.begin() + std::ptrdiff_t(start), order.end());
  return cost;
}

namespace {

// A directional light seen from the eye, d = eye - light (world): the factor its intensity is
// multiplied by (0: the eye lies outside its beam) and, in `colour`, the colour it shows.
// * below: a PAPI (or VASI) unit shows white above its transition angle and red below it, the
//   angle measured against the world horizontal: below when d.z < sin(transition) |d|, no trigonometry.
// * beam: the isocandela ellipse of ICAO Annex 14 Vol I, Appendix 2 (runway edge, threshold, end
//   and approach lights): f = 1 - (da/h)^2 - (de/v)^2 for the eye's azimuth and elevation off the
//   axis in the object's horizontal frame. The eye outside the rectangle |da| < h, |de| < v is
//   rejected by dot products (cos da > cos h and the elevation bounds' sines, precomputed by the
//   world database); inside it the lobe needs the two angles.
// `ops` (processor 2) gains what ran; sqrt and atan2 count as 1 D each (GeometryStats).
double directional_light(const WorldLightDirection& w, const glm::dvec3& d, Rgb& colour, OperationCounts& ops) {
  ops.C += 2;  // the below and beam flags
  if (w.below) {
    ops.M += 3 + 1;  // |d|: 3 M + 2 A + sqrt (1 D); sin_below |d|: 1 M; the test: 1 C
    ops.A += 2;
    ops.D += 1;
    ops.C += 1;
    if (d.z < w.sin_below * glm::length(d)) colour = w.below_colour;
  }
  if (!w.beam) return 1;
  const double x = glm::dot(d, w.right), y = glm::dot(d, w.along), z = glm::dot(d, w.up);
  const double r = std::sqrt(x * x + y * y);  // the horizontal distance: z = |d| sin el, r = |d| cos el
  // Three dot products (3 M + 2 A each); r: 2 M + 1 A + sqrt (1 D).
  ops.M += 9 + 2;
  ops.A += 6 + 1;
  ops.D += 1;
  // The rectangle's three tests, each counted when it runs (the first failing one ends it).
  ops.M += 1;
  ops.C += 1;
  if (y < w.cos_horizontal * r) return 0;
  ops.M += 2;
  ops.A += 1;
  ops.C += 1;
  if (z * w.cos_lo - r * w.sin_lo < 0) return 0;
  ops.M += 2;
  ops.A += 1;
  ops.C += 1;
  if (r * w.sin_hi - z * w.cos_hi < 0) return 0;
  const double da = std::atan2(x, y) / w.horizontal;  // in [-pi, pi]: the azimuth off the axis, wrapped
  const double de = (std::atan2(z, r) - w.elevation) / w.vertical;
  ops.D += 4;      // two atan2 (1 D each), two divisions
  ops.A += 1 + 2;  // - elevation; 1 - da^2 - de^2: 2 M + 2 A; max: 1 C
  ops.M += 2;
  ops.C += 1;
  return std::max(0.0, 1 - da * da - de * de);
}

// Processor 1's eye transform of n points, eye = B (p - eye): 3 A for p - eye, 9 M + 6 A for the
// dmat3 * dvec3; 3 L read and 3 L written to the real-number channel.
void eye_transform_ops(OperationCounts& ops, std::uint64_t n) {
  ops.L += 6 * n;
  ops.M += 9 * n;
  ops.A += 9 * n;
}

// Processor 2's perspective division of n points (project): x / (t z) and -y / (t z) as the code
// does them, 2 M + 2 D (t z formed twice; the sign is free); two clamps, 4 C; Xs, Ys, Zs, Is
// written, 4 L.
void project_ops(GeometryStats& stats, std::uint64_t n) {
  stats.divisions += n;
  stats.clip_ops.M += 2 * n;
  stats.clip_ops.D += 2 * n;
  stats.clip_ops.C += 4 * n;
  stats.clip_ops.L += 4 * n;
}

// One channel's stage-B state: the view, its pyramid, and the list being built.
struct ChannelGeometry {
  const ChannelView& view;
  const ViewPyramid pyramid;
  const double tan_half_fov;
  const double min_ds;  // the smallest light diameter, Ds = D / 2048
  ScreenFrame& out;
  GeometryStats& stats;
  std::vector<glm::dvec3> eye;  // the subobject's vertices in eye space, and their outcodes
  std::vector<std::uint8_t> code;
  std::vector<std::uint32_t> order;  // the subobject's polygons in priority order

  // Light points first: they take priority over their own object's surfaces (a runway light over
  // the runway) but not over nearer objects, which come earlier in the list.
  // Directional lights (beam, below) are decided here, as a real CIG's light-point processor does,
  // so every engine gets them through the list: a light whose beam misses the eye is not listed.
  void light_points(const Object& object, const WorldObject& wobject, std::uint32_t object_index) {
    stats.light_points_in += object.light_points.size();
    std::size_t next = 0;  // the next of the object's directional lights
    for (std::size_t i = 0; i < object.light_points.size(); ++i) {
      const WorldLightDirection* dir = nullptr;
      if (next < wobject.light_directions.size() && wobject.light_directions[next].light == i)
        dir = &wobject.light_directions[next++];
      const glm::dvec3 e = view.to_eye(wobject.light_positions[i]);
      eye_transform_ops(stats.transform_ops, 1);
      stats.clip_ops.L += 3;  // outcode: the eye read, 5 x (3 M + 3 A + 1 C), 1 C (inside?)
      stats.clip_ops.M += 15;
      stats.clip_ops.A += 15;
      stats.clip_ops.C += 5 + 1;
      if (pyramid.outcode(e)) continue;  // kept when the centre is inside the pyramid
      const LightPoint& lp = object.light_points[i];
      ScreenLightPoint s;
      s.colour = lp.colour;
      double f = 1;
      if (dir) {
        stats.clip_ops.A += 3;  // d = eye - p
        stats.clip_ops.C += 1;  // f > 0
      }
      if (dir &&
          !((f = directional_light(*dir, view.eye - wobject.light_positions[i], s.colour, stats.clip_ops)) > 0)) {
        ++stats.light_points_outside_beam;
        continue;
      }
      const ScreenVertex c = project(e, lp.intensity, tan_half_fov);
      // As a vertex's projection (project_ops), then Ds = D/(t z): 1 M + 1 D + 2 C (min, max);
      // I f: 1 M; Ds written too.
      project_ops(stats, 1);
      stats.clip_ops.M += 1 + 1;
      stats.clip_ops.D += 1;
      stats.clip_ops.C += 2;
      stats.clip_ops.L += 1;
      s.xs = c.xs;
      s.ys = c.ys;
      s.zs = c.zs;
      s.ds = std::min(1.0, std::max(min_ds, lp.diameter / (tan_half_fov * e.z)));
      s.intensity = lp.intensity * f;
      s.priority = std::int32_t(out.polygons.size());
      s.object = std::int32_t(object_index);
      s.light = std::int32_t(i);
      out.light_points.push_back(s);
    }
  }

  // Back-face cull, trivial reject, clip and project one polygon; false when nothing is left.
  bool polygon(const Polygon& poly, const WorldSubobject& w, std::uint32_t pi, ScreenPolygon& sp) {
    // Back face: the observer is not on the front side of the polygon's plane. Processor 1:
    // the plane read (4 L), n . eye (3 M + 2 A), the test (1 C).
    stats.transform_ops.L += 4;
    stats.transform_ops.M += 3;
    stats.transform_ops.A += 2;
    stats.transform_ops.C += 1;
    if (glm::dot(w.face_normal[pi], view.eye) <= w.face_offset[pi]) {
      ++stats.backfacing;
      return false;
    }
    std::uint8_t all = 0xff, any = 0;
    for (auto i : poly.indices) {
      all &= code[i];
      any |= code[i];
    }
    const std::uint64_t n = poly.indices.size();
    stats.clip_ops.L += n;      // outcodes read
    stats.clip_ops.O += 2 * n;  // AND, OR
    stats.clip_ops.C += 1;      // all outside one plane?
    if (all) {
      ++stats.outside;
      return false;
    }
    ClipPolygon cp;
    for (std::size_t k = 0; k < poly.indices.size(); ++k)
      cp.v[cp.n++] = {eye[poly.indices[k]], w.corner_intensity[w.first_corner[pi] + k]};
    stats.clip_ops.L += 4 * n;  // eye and intensity into the clipping buffer
    stats.clip_ops.C += 1;      // any plane crossed?
    if (any) {
      ++stats.clipped;
      ClipCount count;
      const bool kept = clip_polygon(cp, pyramid, any, count);
      stats.clip_ops += count.ops;
      stats.clip_intersections += count.intersections;
      if (!kept) {
        ++stats.outside;
        return false;
      }
    }
    sp.vertices.reserve(std::size_t(cp.n));
    for (int k = 0; k < cp.n; ++k) sp.vertices.push_back(project(cp.v[k].eye, cp.v[k].intensity, tan_half_fov));
    project_ops(stats, std::uint64_t(cp.n));
    // Polygons seen exactly edge-on (or clipped to a sliver of no area) cover nothing.
    // Per vertex a.xs b.ys - b.xs a.ys summed: 2 M + 2 A; the test: 1 C.
    stats.clip_ops.M += 2 * std::uint64_t(cp.n);
    stats.clip_ops.A += 2 * std::uint64_t(cp.n);
    stats.clip_ops.C += 1;
    double area2 = 0;
    for (int k = 0; k < cp.n; ++k) {
      const auto& a = sp.vertices[std::size_t(k)];
      const auto& b = sp.vertices[std::size_t((k + 1) % cp.n)];
      area2 += a.xs * b.ys - b.xs * a.ys;
    }
    if (!(std::abs(area2) > 1e-18)) {
      ++stats.degenerate;
      return false;
    }
    return true;
  }

  void subobject(const Subobject& sub, const WorldSubobject& w, std::uint32_t object_index, std::uint32_t si,
                 bool back_to_front) {
    eye.resize(w.vertices.size());
    code.resize(w.vertices.size());
    for (std::size_t i = 0; i < w.vertices.size(); ++i) {
      eye[i] = view.to_eye(w.vertices[i]);
      code[i] = pyramid.outcode(eye[i]);
    }
    const std::uint64_t n = w.vertices.size();
    stats.vertices_transformed += n;
    eye_transform_ops(stats.transform_ops, n);
    stats.clip_ops.L += 4 * n;  // outcode: the eye read (3 L), 5 x (3 M + 3 A + 1 C), written (1 L)
    stats.clip_ops.M += 15 * n;
    stats.clip_ops.A += 15 * n;
    stats.clip_ops.C += 5 * n;
    stats.polygons_in += sub.polygons.size();
    if (sub.bsp.empty()) {  // the modeller's list as it is
      for (std::uint32_t pi = 0; pi < sub.polygons.size(); ++pi) emit(sub, w, object_index, si, pi);
      return;
    }
    order.clear();
    ++stats.bsp_subobjects;
    stats.bsp.add(walk_priority_tree(sub.bsp, w, view.eye, back_to_front, order));
    for (std::uint32_t pi : order) emit(sub, w, object_index, si, pi);
  }

  // Polygon pi of the subobject onto the list, unless culled or clipped away.
  void emit(const Subobject& sub, const WorldSubobject& w, std::uint32_t object_index, std::uint32_t si,
            std::uint32_t pi) {
    const Polygon& poly = sub.polygons[pi];
    ScreenPolygon sp;
    if (!polygon(poly, w, pi, sp)) return;
    sp.colour = poly.colour;
    sp.opaque = poly.opaque;
    sp.protect = poly.protect;
    sp.object = std::int32_t(object_index);
    sp.subobject = std::int32_t(si);
    sp.polygon = std::int32_t(pi);
    stats.vertices_out += sp.vertices.size();
    out.polygons.push_back(std::move(sp));
  }
};

// Stage F's input: every convex polyhedron of the list, once, in the order of its first entry, its
// faces as eye-space planes of stage F's frame (y down: the screen's Ys), each with the polygons of
// f.polygons drawn on it (the first is EyeFace::polygon). A world plane n.p = D becomes, for e = R (p - eye),
// (R n).e = D - n.eye; the y flip changes n and e alike.
void eye_polyhedra(const Scene& scene, const WorldDatabase& db, const ChannelView& view, const PriorityList& list,
                   ScreenFrame& f, OperationCounts& transform_ops) {
  std::vector<std::int32_t> slot(scene.objects.size(), -1);  // object -> its entry in f.polyhedra
  for (const PriorityEntry& entry : list.objects) {
    const std::uint32_t o = entry.object;
    if (!scene.objects[o].polyhedron || scene.objects[o].hull.faces.empty() || slot[o] >= 0) continue;
    slot[o] = std::int32_t(f.polyhedra.size());
    EyePolyhedron p;
    p.object = std::int32_t(o);
    const WorldObject& w = db.objects[o];
    for (std::size_t k = 0; k < w.hull_normal.size(); ++k) {
      const glm::dvec3 n = view.world_to_eye * w.hull_normal[k];
      EyeFace face;
      face.nx = n.x;
      face.ny = -n.y;
      face.nz = n.z;
      face.d = w.hull_offset[k] - glm::dot(w.hull_normal[k], view.eye);
      p.faces.push_back(face);
      transform_ops.M += 9 + 3;  // R n: 9 M + 6 A; D - n . eye: 3 M + 3 A (processor 1)
      transform_ops.A += 6 + 3;
      transform_ops.L += 4 + 4;  // plane read, eye plane written
    }
    f.polyhedra.push_back(std::move(p));
  }
  for (std::size_t i = 0; i < f.polygons.size(); ++i) {
    const ScreenPolygon& sp = f.polygons[i];
    const std::int32_t s = slot[std::size_t(sp.object)];
    if (s < 0) continue;
    const Polyhedron& hull = scene.objects[std::size_t(sp.object)].hull;
    EyeFace& face = f.polyhedra[std::size_t(s)]
                        .faces[std::size_t(hull.face_of[std::size_t(sp.subobject)][std::size_t(sp.polygon)])];
    if (face.polygon < 0) face.polygon = std::int32_t(i);
    face.pieces.push_back(std::int32_t(i));
  }
}

}  // namespace

ScreenFrame process_channel(const Scene& scene, const WorldDatabase& db, const ChannelView& view,
                            const PriorityList& list, GeometryStats& stats) {
  const auto t0 = Clock::now();
  ScreenFrame f;
  f.raster = scene.raster;
  f.frame = view.frame;
  f.channel = view.channel;
  f.fog = scene.fog;
  f.background = scene.background;
  ChannelGeometry g{view,
                    ViewPyramid(view.tan_half_fov, view.near),
                    view.tan_half_fov,
                    std::ldexp(scene.light_rendering.min_diameter_units, -hls::kGridScaleLog2),
                    f,
                    stats,
                    {},
                    {},
                    {}};
  for (const PriorityEntry& entry : list.objects) {
    const Object& object = scene.objects[entry.object];
    const WorldObject& wobject = db.objects[entry.object];
    if (entry.lights) g.light_points(object, wobject, entry.object);
    for (std::uint32_t si : list.run(entry))
      g.subobject(object.subobjects[si], wobject.subobjects[si], entry.object, si, list.back_to_front);
  }
  f.tan_half_fov = view.tan_half_fov;
  f.near = view.near;
  f.lists_polyhedra = db.has_polyhedra;
  if (db.has_polyhedra) eye_polyhedra(scene, db, view, list, f, stats.transform_ops);
  stats.polygons_out += f.polygons.size();
  stats.light_points_out += f.light_points.size();
  stats.ms += ms_since(t0);
  return f;
}

}  // namespace cig
