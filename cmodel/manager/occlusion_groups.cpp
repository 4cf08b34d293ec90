#include "manager/occlusion_groups.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <queue>

namespace cig {

namespace {

// The seed's test: the spheres overlap (|c_i - c_j| < R_i + R_j), within one layer.
bool overlap(const GroupSphere& a, const GroupSphere& b) {
  if (a.layer != b.layer) return false;
  const glm::dvec3 d = a.centre - b.centre;
  const double r = a.radius + b.radius;
  return d.x * d.x + d.y * d.y + d.z * d.z < r * r;
}

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[std::size_t(x)] != x) x = parent[std::size_t(x)] = parent[std::size_t(parent[std::size_t(x)])];
    return x;
  }
  void join(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::size_t(std::max(a, b))] = std::min(a, b);
  }
};

// Groups numbered in order of their first sphere.
SphereGroups label(UnionFind& uf, std::uint64_t tests) {
  SphereGroups g;
  g.pair_tests = tests;
  g.group.assign(uf.parent.size(), -1);
  std::vector<int> number(uf.parent.size(), -1);
  for (std::size_t i = 0; i < uf.parent.size(); ++i) {
    const std::size_t root = std::size_t(uf.find(int(i)));
    if (number[root] < 0) number[root] = g.count++;
    g.group[i] = number[root];
  }
  return g;
}

}  // namespace

double eye_power(const GroupSphere& s) {
  return s.centre.x * s.centre.x + s.centre.y * s.centre.y + s.centre.z * s.centre.z - s.radius * s.radius;
}

SphereGroups groups_pairwise(const std::vector<GroupSphere>& spheres) {
  UnionFind uf(spheres.size());
  std::uint64_t tests = 0;
  for (std::size_t i = 0; i < spheres.size(); ++i)
    for (std::size_t j = i + 1; j < spheres.size(); ++j) {
      ++tests;
      if (overlap(spheres[i], spheres[j])) uf.join(int(i), int(j));
    }
  return label(uf, tests);
}

SphereGroups groups_by_sweep(const std::vector<GroupSphere>& spheres) {
  std::vector<int> order(spheres.size());
  std::iota(order.begin(), order.end(), 0);
  auto lo = [&](int i) { return spheres[std::size_t(i)].centre.x - spheres[std::size_t(i)].radius; };
  auto hi = [&](int i) { return spheres[std::size_t(i)].centre.x + spheres[std::size_t(i)].radius; };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return lo(a) < lo(b); });
  UnionFind uf(spheres.size());
  std::uint64_t tests = 0;
  for (std::size_t k = 0; k < order.size(); ++k) {
    // The later spheres (in x order) whose extent starts before this one's ends; the margin keeps
    // every pair the exact test could accept (rounding of hi and lo).
    const int a = order[k];
    const double end = hi(a) + 1e-12 * (std::abs(hi(a)) + 1.0);
    for (std::size_t m = k + 1; m < order.size() && lo(order[m]) <= end; ++m) {
      ++tests;
      if (overlap(spheres[std::size_t(a)], spheres[std::size_t(order[m])])) uf.join(a, order[m]);
    }
  }
  return label(uf, tests);
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> merge_by_distance(
    const std::vector<std::vector<MergeItem>>& lists) {
  using Head = std::pair<double, std::uint32_t>;  // (distance of the list's next entry, list)
  std::priority_queue<Head, std::vector<Head>, std::greater<Head>> heads;
  std::vector<std::uint32_t> next(lists.size(), 0);
  std::size_t total = 0;
  for (std::uint32_t k = 0; k < lists.size(); ++k) {
    total += lists[k].size();
    if (!lists[k].empty()) heads.push({lists[k][0].distance, k});
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  out.reserve(total);
  while (!heads.empty()) {
    const std::uint32_t k = heads.top().second;
    heads.pop();
    out.push_back({k, next[k]});
    if (++next[k] < lists[k].size()) heads.push({lists[k][next[k]].distance, k});
  }
  return out;
}

}  // namespace cig
