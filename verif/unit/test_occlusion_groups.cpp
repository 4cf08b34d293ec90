// Occlusion groups and subobject priority of seed 000 (cmodel/manager/occlusion_groups.hpp):
//  * the sweep finds the same groups as the seed's pair loop, on random scenes of clustered
//    spheres of very different radii;
//  * the eye's power |c|^2 - R^2 is a valid front-to-back order for non-overlapping spheres
//    (checked with rays: whenever a ray meets A before B, A comes first), and the distance to the
//    centre is not (the same rays find it wrong);
//  * the k-way merge keeps each list's order and takes the nearest head, ties to the earlier list;
//  * on the airfield the manager lists every visible subobject once, the pair loop gives the same
//    list as the sweep, and back to front is the exact reverse.
#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include <gtest/gtest.h>

#include "manager/occlusion_groups.hpp"
#include "manager/scene_manager.hpp"
#include "scene/scene_loader.hpp"
#include "test_support.hpp"

namespace cig {
namespace {

std::vector<GroupSphere> random_spheres(std::mt19937_64& rng, int count, bool disjoint) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<GroupSphere> out;
  for (int tries = 0; int(out.size()) < count && tries < 100000; ++tries) {
    // Clusters (towns) and scattered spheres, radii over four decades.
    const double cluster = std::floor(unit(rng) * 5);
    GroupSphere s;
    s.centre = {cluster * 300 - 600 + unit(rng) * 200, unit(rng) * 100 - 50, 50 + cluster * 200 + unit(rng) * 400};
    s.radius = std::pow(10.0, unit(rng) * 4 - 1.5);
    s.layer = unit(rng) < 0.1 ? -1 : 0;
    if (disjoint) {
      bool clear = s.radius < 200;
      for (const GroupSphere& o : out) clear = clear && glm::length(o.centre - s.centre) > o.radius + s.radius;
      if (!clear) continue;
    }
    out.push_back(s);
  }
  return out;
}

TEST(OcclusionGroups, SweepFindsThePairLoopsGroups) {
  std::mt19937_64 rng(7);
  long grouped = 0;
  for (int scene = 0; scene < 200; ++scene) {
    const std::vector<GroupSphere> s = random_spheres(rng, 1 + scene % 150, false);
    const SphereGroups a = groups_pairwise(s), b = groups_by_sweep(s);
    ASSERT_EQ(a.count, b.count) << "scene " << scene;
    ASSERT_EQ(a.group, b.group) << "scene " << scene;  // both number groups by their first sphere
    EXPECT_EQ(a.pair_tests, std::uint64_t(s.size()) * (s.size() - 1) / 2);
    EXPECT_LE(b.pair_tests, a.pair_tests);
    grouped += long(s.size()) - a.count;
  }
  EXPECT_GT(grouped, 1000);  // the scenes do group
}

// Entry distance of the ray t u (|u| = 1) into the sphere, or -1 when it misses.
double entry(const glm::dvec3& u, const GroupSphere& s) {
  const double b = glm::dot(u, s.centre), c = glm::dot(s.centre, s.centre) - s.radius * s.radius;
  const double disc = b * b - c;
  if (disc < 0) return -1;
  const double t = b - std::sqrt(disc);
  return t > 0 ? t : -1;
}

TEST(OcclusionGroups, PowerIsAVisibilityOrderAndCentreDistanceIsNot) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  long checked = 0, power_wrong = 0, distance_wrong = 0;
  for (int scene = 0; scene < 40; ++scene) {
    const std::vector<GroupSphere> s = random_spheres(rng, 60, true);
    for (int ray = 0; ray < 4000; ++ray) {
      const glm::dvec3 u = glm::normalize(glm::dvec3(unit(rng) * 0.8, unit(rng) * 0.2, 1.0));
      for (std::size_t a = 0; a < s.size(); ++a) {
        const double ta = entry(u, s[a]);
        if (ta < 0) continue;
        for (std::size_t b = 0; b < s.size(); ++b) {
          const double tb = entry(u, s[b]);
          if (b == a || tb < 0 || !(ta < tb)) continue;  // the ray meets a first
          ++checked;
          power_wrong += eye_power(s[a]) > eye_power(s[b]) ? 1 : 0;
          distance_wrong += glm::length(s[a].centre) > glm::length(s[b].centre) ? 1 : 0;
        }
      }
    }
  }
  // Adversarial pairs: a small sphere just behind a large one, on a ray grazing the large one
  // inside its silhouette (there the large sphere's surface is nearer than its centre).
  std::uniform_real_distribution<double> fraction(0.0, 1.0);
  for (int k = 0; k < 2000; ++k) {
    GroupSphere big{{unit(rng) * 500, unit(rng) * 100, 500 + fraction(rng) * 1500}, 0, 0};
    big.radius = glm::length(big.centre) * (0.1 + 0.4 * fraction(rng));
    const glm::dvec3 axis = glm::normalize(big.centre);
    const glm::dvec3 side = glm::normalize(glm::cross(axis, glm::dvec3(0, 1, 0)));
    const double silhouette = std::asin(big.radius / glm::length(big.centre));
    const double angle = silhouette * (0.999 + 0.00099 * fraction(rng));
    const glm::dvec3 u = std::cos(angle) * axis + std::sin(angle) * side;
    const double b = glm::dot(u, big.centre), c = glm::dot(big.centre, big.centre) - big.radius * big.radius;
    const double exit = b + std::sqrt(b * b - c);
    GroupSphere small{{0, 0, 0}, glm::length(big.centre) * 1e-4, 0};
    small.centre = exit * u;
    for (double step = small.radius; glm::length(small.centre - big.centre) <= big.radius + small.radius; step *= 1.2)
      small.centre = (exit + step) * u;  // just clear of the large sphere, on the ray
    if (!(entry(u, big) >= 0 && entry(u, big) < entry(u, small))) continue;
    ++checked;
    power_wrong += eye_power(big) > eye_power(small) ? 1 : 0;
    distance_wrong += glm::length(big.centre) > glm::length(small.centre) ? 1 : 0;
  }
  EXPECT_GT(checked, 5000);
  EXPECT_EQ(power_wrong, 0);
  EXPECT_GT(distance_wrong, 100);  // the seed's key orders the hidden sphere first
}

TEST(OcclusionGroups, MergeKeepsEachListAndTakesTheNearestHead) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> d(0, 20);
  for (int t = 0; t < 500; ++t) {
    std::vector<std::vector<MergeItem>> lists(std::size_t(1 + t % 6));
    for (auto& l : lists)
      for (int k = d(rng) % 8; k > 0; --k) l.push_back({double(d(rng)), std::uint32_t(l.size())});
    const auto merged = merge_by_distance(lists);
    std::vector<std::uint32_t> next(lists.size(), 0);
    for (const auto& [k, i] : merged) {
      ASSERT_EQ(i, next[k]) << "a list's order changed";
      for (std::size_t o = 0; o < lists.size(); ++o)  // no other head was nearer (or as near and earlier)
        if (next[o] < lists[o].size() && o != k) {
          const double other = lists[o][next[o]].distance, mine = lists[k][i].distance;
          ASSERT_TRUE(other > mine || (other == mine && o > k));
        }
      ++next[k];
    }
    for (std::size_t k = 0; k < lists.size(); ++k) ASSERT_EQ(next[k], lists[k].size());
  }
}

TEST(OcclusionGroups, AirfieldListsEverySubobjectOnceInEitherOrder) {
  const Scene scene = load_scene(test::source_path("scenes/airfield.json"));
  const WorldDatabase db = build_world_database(scene);
  long grouped = 0;
  for (int frame : {0, 60, 149})
    for (int channel = 0; channel < int(scene.channels.size()); ++channel) {
      const ChannelView view = make_channel_view(scene, frame, channel);
      SceneManagerStats st, st_pairs, st_back;
      const PriorityList list = manage_channel(db, view, st);
      ManagerOptions pairs, back;
      pairs.pairwise_groups = true;
      back.back_to_front = true;
      const PriorityList by_pairs = manage_channel(db, view, st_pairs, pairs);
      const PriorityList reversed = manage_channel(db, view, st_back, back);
      std::vector<std::pair<std::uint32_t, std::uint32_t>> order, order_pairs, order_back;
      std::map<std::uint32_t, int> light_runs;
      for (const PriorityEntry& e : list.objects) {
        light_runs[e.object] += e.lights ? 1 : 0;
        for (std::uint32_t s : list.run(e)) order.push_back({e.object, s});
      }
      for (const PriorityEntry& e : by_pairs.objects)
        for (std::uint32_t s : by_pairs.run(e)) order_pairs.push_back({e.object, s});
      for (const PriorityEntry& e : reversed.objects)
        for (std::uint32_t s : reversed.run(e)) order_back.push_back({e.object, s});
      EXPECT_EQ(order.size(), st.subobjects_visible);
      auto sorted = order;
      std::sort(sorted.begin(), sorted.end());
      EXPECT_TRUE(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) << "a subobject twice";
      EXPECT_EQ(order, order_pairs);
      std::reverse(order_back.begin(), order_back.end());
      EXPECT_EQ(order, order_back);
      for (const auto& [object, runs] : light_runs) EXPECT_EQ(runs, 1) << "object " << object;
      EXPECT_EQ(st.groups, st_pairs.groups);
      EXPECT_GT(st_pairs.pair_tests, st.pair_tests);
      grouped += long(st.grouped_objects);
    }
  EXPECT_GT(grouped, 0);
}

}  // namespace
}  // namespace cig
