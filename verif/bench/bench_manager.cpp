// The scene manager's front end per channel (SPEC A: the quadtree culling of seed 003, the sphere
// tests, the occlusion groups and the subobject merge of seed 000) on a world of 10^4 to 10^5
// objects: towns of houses, forests, scattered objects and large terrain tiles over 60 km, three
// subobjects each, seen from views along a low flight over it. One case per culling method; brute
// force is the baseline (every object's sphere). Counters: objects, visible objects, nodes kept.
#include <cmath>
#include <memory>
#include <random>

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include "manager/scene_manager.hpp"
#include "manager/scene_quadtree.hpp"

namespace cig {
namespace {

WorldDatabase synthetic_world(int objects) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double side = 60000 * std::sqrt(objects / 100000.0);
  WorldDatabase db;
  db.objects.reserve(std::size_t(objects));
  for (int i = 0; i < objects; ++i) {
    WorldObject o;
    const double kind = unit(rng);
    const glm::dvec3 town(std::floor(unit(rng) * 12) * side / 12, std::floor(unit(rng) * 12) * side / 12, 0);
    if (kind < 0.02) {  // terrain tile
      o.centre = {unit(rng) * side, unit(rng) * side, 0};
      o.radius = 700;
      o.layer = -1;           // the ground: drawn after everything on it, never grouped with it
    } else if (kind < 0.6) {  // a house of a town
      o.centre = town + glm::dvec3(unit(rng) * 1500, unit(rng) * 1500, 4);
      o.radius = 6 + unit(rng) * 10;
    } else {  // a tree, a mast, a ship
      o.centre = {unit(rng) * side, unit(rng) * side, 5};
      o.radius = 3 + unit(rng) * 30;
    }
    for (int s = 0; s < 3; ++s) {
      WorldSubobject sub;
      sub.centre = o.centre + glm::dvec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5) * o.radius;
      sub.radius = 0.5 * o.radius;
      o.subobjects.push_back(sub);
    }
    db.objects.push_back(std::move(o));
  }
  return db;
}

// View k of a low flight diagonally over the world, heading along it, 10 degrees down, 40 degrees
// field of view (the airfield's channels), a 12 km visibility range.
ChannelView flight_view(double side, int k) {
  ChannelView v;
  const double a = 0.1 + 0.8 * (k % 64) / 64.0;
  v.eye = {a * side, a * side * 0.9, 300};
  const double heading = 0.73 + 0.4 * std::sin(k), pitch = -0.17;
  const glm::dvec3 f(std::cos(pitch) * std::cos(heading), std::cos(pitch) * std::sin(heading), std::sin(pitch));
  const glm::dvec3 r = glm::normalize(glm::cross(f, glm::dvec3(0, 0, 1)));
  v.world_to_eye = glm::transpose(glm::dmat3(r, glm::cross(r, f), f));
  v.tan_half_fov = std::tan(20.0 * 3.14159265358979 / 180);
  v.near = 1;
  v.range = 12000;  // the visibility range of a 12 km fog (Scene::range)
  return v;
}

void front_end(benchmark::State& state) {
  const int objects = int(state.range(0));
  const CullMethod method = CullMethod(state.range(1));
  static WorldDatabase db;
  static std::unique_ptr<SceneQuadtree> tree;
  if (int(db.objects.size()) != objects) {
    db = synthetic_world(objects);
    tree = std::make_unique<SceneQuadtree>(db);
  }
  ManagerOptions o;
  o.tree = method == CullMethod::kBruteForce ? nullptr : tree.get();
  o.culling.method = method;
  const double side = 60000 * std::sqrt(objects / 100000.0);
  SceneManagerStats st;
  int k = 0;
  for (auto _ : state) {
    PriorityList list = manage_channel(db, flight_view(side, k++), st, o);
    benchmark::DoNotOptimize(list);
  }
  const double n = double(state.iterations());
  state.counters["objects"] = objects;
  state.counters["visible"] = double(st.objects_visible) / n;
  state.counters["nodes_kept"] = double(st.cull.nodes_kept) / n;
  state.counters["groups"] = double(st.groups) / n;
  state.SetLabel(cull_method_name(method));
}

BENCHMARK(front_end)
    ->ArgNames({"objects", "method"})
    ->ArgsProduct({{10000, 100000},
                   {int(CullMethod::kLineOfSight), int(CullMethod::kProjection), int(CullMethod::kHierarchical),
                    int(CullMethod::kBruteForce)}})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace cig

BENCHMARK_MAIN();
