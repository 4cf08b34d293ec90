#include "manager/scene_quadtree.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "common/error.hpp"
#include "common/timing.hpp"

namespace cig {

CullMethod parse_cull_method(const std::string& text) {
  if (text == "line-of-sight") return CullMethod::kLineOfSight;
  if (text == "hierarchical") return CullMethod::kHierarchical;
  if (text == "projection") return CullMethod::kProjection;
  if (text == "brute-force") return CullMethod::kBruteForce;
  throw InputError("", "--culling",
                   "'" + text + "' is not one of line-of-sight, hierarchical, projection, brute-force");
}

const char* cull_method_name(CullMethod m) {
  switch (m) {
    case CullMethod::kLineOfSight:
      return "line-of-sight";
    case CullMethod::kHierarchical:
      return "hierarchical";
    case CullMethod::kProjection:
      return "projection";
    default:
      return "brute-force";
  }
}

namespace {

struct Box {
  glm::dvec3 lo, hi;
};

Box sphere_box(const WorldObject& o) { return {o.centre - glm::dvec3(o.radius), o.centre + glm::dvec3(o.radius)}; }

// Which quadrant of the split at mid holds the box wholly, or -1 when it straddles.
int quadrant(const Box& b, const glm::dvec2& mid) {
  const int qx = b.hi.x <= mid.x ? 0 : (b.lo.x >= mid.x ? 1 : -1);
  const int qy = b.hi.y <= mid.y ? 0 : (b.lo.y >= mid.y ? 1 : -1);
  return qx < 0 || qy < 0 ? -1 : 2 * qy + qx;
}

// A plane of the viewing pyramid in world coordinates: n . p + d >= 0 inside.
struct WorldPlane {
  glm::dvec3 n;
  double d, norm;
};

enum class Side { kOutside, kPartial, kInside };

std::vector<WorldPlane> world_planes(const ChannelView& view) {
  const ViewPyramid pyramid(view.tan_half_fov, view.near);
  std::vector<WorldPlane> out;
  for (const ClipPlane& p : pyramid.plane) {
    // eye = W (x - eye0): a . eye + d = (W^T a) . x + d - (W^T a) . eye0.
    const glm::dvec3 n = glm::transpose(view.world_to_eye) * glm::dvec3(p.a, p.b, p.c);
    out.push_back({n, p.d - glm::dot(n, view.eye), glm::length(n)});
  }
  if (std::isfinite(view.range)) {  // the visibility range: -z + range >= 0
    const glm::dvec3 n = glm::transpose(view.world_to_eye) * glm::dvec3(0, 0, -1);
    out.push_back({n, view.range - glm::dot(n, view.eye), 1.0});
  }
  return out;
}

Side sphere_side(const std::vector<WorldPlane>& planes, const glm::dvec3& c, double r) {
  bool inside = true;
  for (const WorldPlane& p : planes) {
    const double s = glm::dot(p.n, c) + p.d;
    if (s < -r * p.norm) return Side::kOutside;
    inside = inside && s >= r * p.norm;
  }
  return inside ? Side::kInside : Side::kPartial;
}

Side box_side(const std::vector<WorldPlane>& planes, const glm::dvec3& lo, const glm::dvec3& hi) {
  bool inside = true;
  for (const WorldPlane& p : planes) {
    const glm::dvec3 far(p.n.x >= 0 ? hi.x : lo.x, p.n.y >= 0 ? hi.y : lo.y, p.n.z >= 0 ? hi.z : lo.z);
    const glm::dvec3 near(p.n.x >= 0 ? lo.x : hi.x, p.n.y >= 0 ? lo.y : hi.y, p.n.z >= 0 ? lo.z : hi.z);
    if (glm::dot(p.n, far) + p.d < 0) return Side::kOutside;
    inside = inside && glm::dot(p.n, near) + p.d >= 0;
  }
  return inside ? Side::kInside : Side::kPartial;
}

// The sphere, then the box where the sphere does not decide.
Side sphere_then_box(const std::vector<WorldPlane>& planes, const glm::dvec3& c, double r, const glm::dvec3& lo,
                     const glm::dvec3& hi) {
  const Side s = sphere_side(planes, c, r);
  if (s != Side::kPartial) return s;
  return box_side(planes, lo, hi);
}

// The pyramid's footprint on the ground plane: the convex hull (counter-clockwise) of its apex,
// moved back by `back` along the line of sight, and its four corners at depth `depth` from there,
// projected onto x, y.
std::vector<glm::dvec2> footprint(const ChannelView& view, double back, double depth) {
  const glm::dmat3 to_world = glm::transpose(view.world_to_eye);
  const glm::dvec3 apex = view.eye - back * (to_world * glm::dvec3(0, 0, 1));
  const double s = view.tan_half_fov * depth;
  std::vector<glm::dvec2> p{{apex.x, apex.y}};
  for (int k = 0; k < 4; ++k) {
    const glm::dvec3 w = apex + to_world * glm::dvec3(k & 1 ? s : -s, k & 2 ? s : -s, depth);
    p.push_back({w.x, w.y});
  }
  std::sort(p.begin(), p.end(), [](auto a, auto b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  auto cross = [](glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  std::vector<glm::dvec2> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {  // Andrew's monotone chain
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  hull.resize(k > 1 ? k - 1 : k);
  return hull;
}

// The 2D box against the convex footprint (separating axes: the box's and the hull's edges).
bool box_meets_footprint(const std::vector<glm::dvec2>& hull, const glm::dvec3& lo, const glm::dvec3& hi) {
  double xmin = hull[0].x, xmax = hull[0].x, ymin = hull[0].y, ymax = hull[0].y;
  for (const glm::dvec2& v : hull) {
    xmin = std::min(xmin, v.x), xmax = std::max(xmax, v.x), ymin = std::min(ymin, v.y), ymax = std::max(ymax, v.y);
  }
  if (hi.x < xmin || lo.x > xmax || hi.y < ymin || lo.y > ymax) return false;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const glm::dvec2 a = hull[i], b = hull[(i + 1) % hull.size()];
    const glm::dvec2 outward(b.y - a.y, a.x - b.x);  // counter-clockwise hull: right of the edge
    const glm::dvec2 corner(outward.x >= 0 ? lo.x : hi.x, outward.y >= 0 ? lo.y : hi.y);  // least along it
    if (glm::dot(outward, corner - a) > 0) return false;
  }
  return true;
}

}  // namespace

SceneQuadtree::SceneQuadtree(const WorldDatabase& db) : db_(db) {
  std::vector<std::uint32_t> ids(db.objects.size());
  for (std::uint32_t i = 0; i < ids.size(); ++i) ids[i] = i;
  glm::dvec2 lo(0), hi(0);
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const Box b = sphere_box(db.objects[i]);
    lo = i == 0 ? glm::dvec2(b.lo) : glm::min(lo, glm::dvec2(b.lo));
    hi = i == 0 ? glm::dvec2(b.hi) : glm::max(hi, glm::dvec2(b.hi));
  }
  const double side = std::max(hi.x - lo.x, hi.y - lo.y);  // square cells
  build(ids, lo, lo + glm::dvec2(side), 0);
}

std::int32_t SceneQuadtree::build(std::vector<std::uint32_t>& ids, glm::dvec2 lo, glm::dvec2 hi, int depth) {
  const std::int32_t index = std::int32_t(nodes_.size());
  nodes_.emplace_back();
  const glm::dvec2 mid = 0.5 * (lo + hi);
  std::vector<std::uint32_t> here, below[4];
  const bool leaf = ids.size() <= std::size_t(kLeafObjects) || depth >= kMaxDepth;
  for (std::uint32_t id : ids) {
    const int q = leaf ? -1 : quadrant(sphere_box(db_.objects[id]), mid);
    (q < 0 ? here : below[q]).push_back(id);
  }
  Node node;
  node.first = std::uint32_t(objects_.size());
  node.count = std::uint32_t(here.size());
  objects_.insert(objects_.end(), here.begin(), here.end());
  bool any = false;
  auto grow = [&](const glm::dvec3& l, const glm::dvec3& h) {
    node.lo = any ? glm::min(node.lo, l) : l;
    node.hi = any ? glm::max(node.hi, h) : h;
    any = true;
  };
  for (std::uint32_t id : here) {
    grow(sphere_box(db_.objects[id]).lo, sphere_box(db_.objects[id]).hi);
    node.largest_object = std::max(node.largest_object, db_.objects[id].radius);
  }
  for (int q = 0; q < 4; ++q) {
    if (below[q].empty()) continue;
    const glm::dvec2 clo(q & 1 ? mid.x : lo.x, q & 2 ? mid.y : lo.y), chi(q & 1 ? hi.x : mid.x, q & 2 ? hi.y : mid.y);
    const std::int32_t c = build(below[q], clo, chi, depth + 1);
    node.child[q] = c;
    grow(nodes_[std::size_t(c)].lo, nodes_[std::size_t(c)].hi);
    node.largest_object = std::max(node.largest_object, nodes_[std::size_t(c)].largest_object);
  }
  node.subtree_end = std::uint32_t(objects_.size());
  node.node_end = std::uint32_t(nodes_.size());
  node.centre = 0.5 * (node.lo + node.hi);
  node.radius = 0.5 * glm::length(node.hi - node.lo);
  nodes_[std::size_t(index)] = node;
  return index;
}

std::vector<std::uint32_t> SceneQuadtree::cull(const ChannelView& view, const CullSettings& settings,
                                               CullStats& stats) const {
  const auto t0 = Clock::now();
  std::vector<std::uint32_t> kept;
  if (settings.method == CullMethod::kBruteForce || nodes_.empty()) {
    kept.resize(db_.objects.size());
    for (std::uint32_t i = 0; i < kept.size(); ++i) kept[i] = i;
    stats.objects_kept += kept.size();
    stats.ms += ms_since(t0);
    return kept;
  }
  const std::vector<WorldPlane> planes = world_planes(view);
  // The projection's hulls, one per octave of the offset radius (2^(level - kOctaveBias) m).
  constexpr int kOctaveBias = 20, kOctaves = 64;
  std::vector<std::vector<glm::dvec2>> hulls(settings.method == CullMethod::kProjection ? kOctaves : 0);
  double reach = 0;  // the farthest corner of the world from the eye bounds every object's depth
  for (int k = 0; k < 8 && !hulls.empty(); ++k) {
    const Node& root = nodes_[0];
    reach = std::max(reach, glm::length(glm::dvec3(k & 1 ? root.hi.x : root.lo.x, k & 2 ? root.hi.y : root.lo.y,
                                                   k & 4 ? root.hi.z : root.lo.z) -
                                        view.eye));
  }
  const double back_per_radius = std::sqrt(1 + view.tan_half_fov * view.tan_half_fov) / view.tan_half_fov;
  auto hull_for = [&](double radius) -> const std::vector<glm::dvec2>& {
    int e = 0;
    std::frexp(std::max(radius, 1e-6), &e);  // radius < 2^e
    const int level = std::clamp(e + kOctaveBias, 0, kOctaves - 1);
    std::vector<glm::dvec2>& h = hulls[std::size_t(level)];
    if (h.empty()) {
      const double back = std::ldexp(1.0, level - kOctaveBias) * back_per_radius * (1 + 1e-9) + 1e-6;
      const double depth = std::min(reach, view.range + std::ldexp(1.0, level - kOctaveBias));
      h = footprint(view, back, std::max(depth, view.near) + back);
    }
    return h;
  };
  std::vector<std::int32_t> stack{0};
  while (!stack.empty()) {
    const std::int32_t self = stack.back();
    const Node& node = nodes_[std::size_t(self)];
    stack.pop_back();
    ++stats.nodes_visited;
    Side side = Side::kPartial;
    const double distance = glm::length(node.centre - view.eye);
    switch (settings.method) {
      case CullMethod::kLineOfSight:
        side = distance <= settings.near_distance ? sphere_side(planes, node.centre, node.radius)
               : distance < settings.far_distance ? sphere_then_box(planes, node.centre, node.radius, node.lo, node.hi)
                                                  : box_side(planes, node.lo, node.hi);
        break;
      case CullMethod::kHierarchical:
        side = sphere_then_box(planes, node.centre, node.radius, node.lo, node.hi);
        break;
      default:
        side = box_meets_footprint(hull_for(node.largest_object), node.lo, node.hi) ? Side::kPartial : Side::kOutside;
    }
    if (side == Side::kOutside) continue;
    if (side == Side::kInside) {  // the whole subtree, untested
      stats.nodes_kept += node.node_end - std::uint32_t(self);
      kept.insert(kept.end(), objects_.begin() + node.first, objects_.begin() + node.subtree_end);
      continue;
    }
    ++stats.nodes_kept;
    kept.insert(kept.end(), objects_.begin() + node.first, objects_.begin() + node.first + node.count);
    for (int q = 3; q >= 0; --q)
      if (node.child[q] >= 0) stack.push_back(node.child[q]);
  }
  stats.objects_kept += kept.size();
  stats.ms += ms_since(t0);
  return kept;
}

}  // namespace cig
