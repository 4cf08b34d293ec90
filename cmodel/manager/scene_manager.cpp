#include "manager/scene_manager.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "common/timing.hpp"
#include "manager/occlusion_groups.hpp"

namespace cig {

bool sphere_may_be_visible(const ViewPyramid& pyramid, const glm::dvec3& c, double r) {
  for (int k = 0; k < kClipPlanes; ++k)
    if (pyramid.plane[k].distance(c) < -r * pyramid.norm[k]) return false;
  return true;
}

namespace {

// The sphere test: the visibility range (Scene::range: wholly deeper spheres are culled), then the
// preliminary processing unit's V[i] against the channel's pyramid (visibility_unit.hpp: the
// hls/manager kernel or its twin).
struct SphereTest {
  VisibilityUnit unit;
  double range;
  SphereTest(const ChannelView& view, VisibilityArith arith) : unit(view, arith), range(view.range) {}
  // world: the sphere's centre in the world; eye: the same in eye coordinates (the model's doubles).
  bool visible(const glm::dvec3& world, const glm::dvec3& eye, double r, SceneManagerStats& stats) const {
    return eye.z - r <= range && unit.visible(world, r, stats.unit);
  }
};

struct VisibleObject {
  std::uint32_t object;
  GroupSphere sphere;  // eye coordinates
};

// The preliminary processing unit: objects whose sphere may meet the viewing pyramid, among those
// the quadtree keeps (every object without a tree).
std::vector<VisibleObject> visible_objects(const WorldDatabase& db, const ChannelView& view, const SphereTest& test,
                                           const ManagerOptions& options, SceneManagerStats& stats) {
  std::vector<std::uint32_t> candidates;
  if (options.tree) candidates = options.tree->cull(view, options.culling, stats.cull);
  const auto t0 = Clock::now();
  std::vector<VisibleObject> visible;
  const std::size_t count = options.tree ? candidates.size() : db.objects.size();
  for (std::size_t k = 0; k < count; ++k) {
    const std::uint32_t i = options.tree ? candidates[k] : std::uint32_t(k);
    const WorldObject& o = db.objects[i];
    const glm::dvec3 c = view.to_eye(o.centre);
    if (test.visible(o.centre, c, o.radius, stats)) visible.push_back({i, {c, o.radius, o.layer}});
  }
  stats.sphere_ms += ms_since(t0);
  return visible;
}

// An object's visible subobjects with the distances to their centres, in its modeller's order (or
// nearest first when the object asks for it), appended to `out`; returns how many.
std::size_t visible_subobjects(const WorldObject& o, const ChannelView& view, const SphereTest& test,
                               SceneManagerStats& stats, std::vector<MergeItem>& out) {
  const std::size_t first = out.size();
  for (std::uint32_t s = 0; s < o.subobjects.size(); ++s) {
    const WorldSubobject& sub = o.subobjects[s];
    const glm::dvec3 c = view.to_eye(sub.centre);
    if (test.visible(sub.centre, c, sub.radius, stats)) out.push_back({glm::length(c), s});
  }
  stats.subobjects_tested += o.subobjects.size();
  stats.subobjects_visible += out.size() - first;
  if (o.subobjects_by_distance)
    std::stable_sort(out.begin() + std::ptrdiff_t(first), out.end(),
                     [](const MergeItem& a, const MergeItem& b) { return a.distance < b.distance; });
  return out.size() - first;
}

// The visible objects in priority order, group by group: groups by layer (higher first), then by
// the least eye power of their members, then by their number; members by power (ties: the
// visible order). Returns the order and each group's start in it (one more entry: the end).
std::vector<std::size_t> ordered_groups(const std::vector<VisibleObject>& visible, const SphereGroups& groups,
                                        std::vector<std::size_t>& starts) {
  std::vector<double> power(visible.size()), group_power(std::size_t(groups.count), 0);
  std::vector<int> group_layer(std::size_t(groups.count), 0);
  std::vector<bool> seen(std::size_t(groups.count), false);
  for (std::size_t v = 0; v < visible.size(); ++v) {
    power[v] = eye_power(visible[v].sphere);
    const std::size_t g = std::size_t(groups.group[v]);
    if (!seen[g] || power[v] < group_power[g]) group_power[g] = power[v];
    group_layer[g] = visible[v].sphere.layer;  // one layer per group
    seen[g] = true;
  }
  struct Key {
    int layer;
    double group_power;
    int group;
    double power;
    std::size_t v;
  };
  std::vector<Key> keys(visible.size());
  for (std::size_t v = 0; v < visible.size(); ++v) {
    const std::size_t g = std::size_t(groups.group[v]);
    keys[v] = {-group_layer[g], group_power[g], groups.group[v], power[v], v};
  }
  std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
    if (a.layer != b.layer) return a.layer < b.layer;  // higher layers first (negated)
    if (a.group_power != b.group_power) return a.group_power < b.group_power;
    if (a.group != b.group) return a.group < b.group;
    return a.power != b.power ? a.power < b.power : a.v < b.v;
  });
  std::vector<std::size_t> order(visible.size());
  for (std::size_t k = 0; k < keys.size(); ++k) order[k] = keys[k].v;
  starts.clear();
  for (std::size_t k = 0; k < order.size(); ++k)
    if (k == 0 || groups.group[order[k]] != groups.group[order[k - 1]]) starts.push_back(k);
  starts.push_back(order.size());
  return order;
}

void count_group(std::size_t size, SceneManagerStats& stats) {
  ++stats.groups;
  if (size < 2) return;
  stats.grouped_objects += size;
  stats.largest_group = std::max<std::uint64_t>(stats.largest_group, size);
  if (stats.group_sizes.size() <= size) stats.group_sizes.resize(size + 1, 0);
  ++stats.group_sizes[size];
}

constexpr std::size_t kScanMergeLists = 8;  // up to this many lists, scan the heads

struct GroupContext {
  const WorldDatabase& db;
  const std::vector<VisibleObject>& visible;
  const ChannelView& view;
  const SphereTest& test;
  SceneManagerStats& stats;
  std::vector<MergeItem> items;  // scratch
};

// An object alone keeps its list.
void emit_single(GroupContext& g, std::size_t v, PriorityList& list) {
  const WorldObject& o = g.db.objects[g.visible[v].object];
  g.items.clear();
  const std::size_t n = visible_subobjects(o, g.view, g.test, g.stats, g.items);
  if (n == 0 && o.light_positions.empty()) return;
  list.objects.push_back({g.visible[v].object, std::uint32_t(list.subobjects.size()), std::uint32_t(n), true});
  for (const MergeItem& m : g.items) list.subobjects.push_back(m.value);
}

// The subobject sorter for a group: its objects' lists merged by distance (the seed's two-list
// merge for k lists: each list keeps its order, the nearest head goes next, ties to the earlier
// list), as runs per object. The lists lie one after another in the scratch buffer.
void emit_group(GroupContext& g, const std::size_t* members, std::size_t count, PriorityList& list) {
  g.items.clear();
  std::vector<std::size_t> start(count), next(count), end(count);
  for (std::size_t k = 0; k < count; ++k) {
    const WorldObject& o = g.db.objects[g.visible[members[k]].object];
    start[k] = next[k] = g.items.size();
    if (visible_subobjects(o, g.view, g.test, g.stats, g.items) == 0 && !o.light_positions.empty())
      list.objects.push_back({g.visible[members[k]].object, std::uint32_t(list.subobjects.size()), 0, true});
    end[k] = g.items.size();
  }
  // The order of the merge: heads scanned in turn for a few lists, a heap (merge_by_distance) for many.
  std::vector<std::size_t> taken_from;
  taken_from.reserve(g.items.size());
  if (count <= kScanMergeLists) {
    for (std::size_t taken = 0; taken < g.items.size(); ++taken) {
      std::size_t best = count;
      for (std::size_t k = 0; k < count; ++k)
        if (next[k] < end[k] && (best == count || g.items[next[k]].distance < g.items[next[best]].distance)) best = k;
      taken_from.push_back(best);
      ++next[best];
    }
  } else {
    std::vector<std::vector<MergeItem>> lists(count);
    for (std::size_t k = 0; k < count; ++k)
      lists[k].assign(g.items.begin() + std::ptrdiff_t(next[k]), g.items.begin() + std::ptrdiff_t(end[k]));
    for (const auto& [k, index] : merge_by_distance(lists)) taken_from.push_back(k);
  }
  next = start;  // rewind
  std::vector<bool> lights_done(count, false);
  for (std::size_t best : taken_from) {
    const std::uint32_t object = g.visible[members[best]].object;
    if (list.objects.empty() || list.objects.back().object != object) {  // a new run of this object
      list.objects.push_back({object, std::uint32_t(list.subobjects.size()), 0, !lights_done[best]});
      lights_done[best] = true;
    }
    list.subobjects.push_back(g.items[next[best]++].value);
    ++list.objects.back().count;
  }
}

void reverse_priority(PriorityList& list) {
  // Both the runs and the subobjects reversed: run k's subobjects move to the mirrored place.
  const std::uint32_t total = std::uint32_t(list.subobjects.size());
  std::reverse(list.subobjects.begin(), list.subobjects.end());
  std::reverse(list.objects.begin(), list.objects.end());
  for (PriorityEntry& e : list.objects) e.first = total - e.first - e.count;
  // Group g's entries [first_g, first_g+1) move to [n - first_g+1, n - first_g).
  const std::uint32_t entries = std::uint32_t(list.objects.size());
  std::vector<std::uint32_t> ends;
  for (std::size_t g = 0; g < list.group_first.size(); ++g)
    ends.push_back(g + 1 < list.group_first.size() ? list.group_first[g + 1] : entries);
  list.group_first.clear();
  for (std::size_t g = ends.size(); g-- > 0;) list.group_first.push_back(entries - ends[g]);
}

}  // namespace

std::vector<std::uint32_t> potentially_visible(const WorldDatabase& db, const ChannelView& view,
                                               const ManagerOptions& options, SceneManagerStats& stats) {
  const SphereTest test(view, options.visibility);
  std::vector<std::uint32_t> ids;
  for (const VisibleObject& v : visible_objects(db, view, test, options, stats)) ids.push_back(v.object);
  std::sort(ids.begin(), ids.end());
  return ids;
}

PriorityList manage_channel(const WorldDatabase& db, const ChannelView& view, SceneManagerStats& stats,
                            const ManagerOptions& options) {
  const SphereTest test(view, options.visibility);
  stats.objects += db.objects.size();
  const std::vector<VisibleObject> visible = visible_objects(db, view, test, options, stats);
  stats.objects_visible += visible.size();
  std::vector<GroupSphere> spheres;
  spheres.reserve(visible.size());
  for (const VisibleObject& v : visible) spheres.push_back(v.sphere);
  const SphereGroups groups = options.pairwise_groups ? groups_pairwise(spheres) : groups_by_sweep(spheres);
  stats.pair_tests += groups.pair_tests;
  std::vector<std::size_t> starts;
  const std::vector<std::size_t> order = ordered_groups(visible, groups, starts);
  PriorityList list;
  list.objects.reserve(visible.size());
  GroupContext context{db, visible, view, test, stats, {}};
  for (std::size_t k = 0; k + 1 < starts.size(); ++k) {
    const std::size_t size = starts[k + 1] - starts[k];
    count_group(size, stats);
    if (list.group_first.empty() || list.group_first.back() != list.objects.size())
      list.group_first.push_back(std::uint32_t(list.objects.size()));
    if (size == 1) emit_single(context, order[starts[k]], list);
    else emit_group(context, order.data() + starts[k], size, list);
  }
  if (!list.group_first.empty() && list.group_first.back() == list.objects.size()) list.group_first.pop_back();
  if (options.back_to_front) reverse_priority(list);
  list.back_to_front = options.back_to_front;
  return list;
}

}  // namespace cig
