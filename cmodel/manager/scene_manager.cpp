#include "manager/scene_manager.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace cig {

bool sphere_may_be_visible(const ViewPyramid& pyramid, const glm::dvec3& c, double r) {
  for (const ClipPlane& p : pyramid.plane)
    if (p.distance(c) < -r * std::sqrt(p.a * p.a + p.b * p.b + p.c * p.c)) return false;
  return true;
}

PriorityList manage_channel(const WorldDatabase& db, const ChannelView& view, SceneManagerStats& stats) {
  struct Visible {
    int layer;
    double distance;
    std::uint32_t object;
  };
  std::vector<Visible> visible;
  const ViewPyramid pyramid(view.tan_half_fov, view.near);
  stats.objects += db.objects.size();
  for (std::uint32_t i = 0; i < db.objects.size(); ++i) {
    const WorldObject& o = db.objects[i];
    glm::dvec3 c = view.to_eye(o.centre);
    if (sphere_may_be_visible(pyramid, c, o.radius)) visible.push_back({o.layer, glm::length(c), i});
  }
  stats.objects_visible += visible.size();
  // Priority layers first (higher first), then the depth sort by distance to the centre
  // (SPEC A.3); stable, so equal keys keep database order.
  std::stable_sort(visible.begin(), visible.end(), [](const Visible& a, const Visible& b) {
    return a.layer != b.layer ? a.layer > b.layer : a.distance < b.distance;
  });
  PriorityList list;
  for (const auto& vis : visible) {
    const WorldObject& o = db.objects[vis.object];
    PriorityEntry entry{vis.object, {}};
    std::vector<std::pair<double, std::uint32_t>> by_distance;
    for (std::uint32_t s = 0; s < o.subobjects.size(); ++s) {
      ++stats.subobjects_tested;
      const WorldSubobject& sub = o.subobjects[s];
      const glm::dvec3 c = view.to_eye(sub.centre);
      if (sphere_may_be_visible(pyramid, c, sub.radius)) {
        by_distance.push_back({glm::length(c), s});
        ++stats.subobjects_visible;
      }
    }
    if (o.subobjects_by_distance)
      std::stable_sort(by_distance.begin(), by_distance.end(),
                       [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& d : by_distance) entry.subobjects.push_back(d.second);
    if (!entry.subobjects.empty() || !o.light_positions.empty()) list.objects.push_back(std::move(entry));
  }
  return list;
}

}  // namespace cig
