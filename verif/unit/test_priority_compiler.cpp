// The priority compiler (scene/priority_compiler.hpp) and stage B's walk of its trees, judged by
// an oracle that shares no code with them: rays cast from the eye to sample points of every
// front-facing polygon; a polygon the ray crosses first (nearer the eye) must come earlier in the
// walk's order. That is what a priority engine needs for every pixel to show the nearest surface.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "geometry/geometric_processor.hpp"
#include "scene/priority_compiler.hpp"
#include "scene/scene_loader.hpp"
#include "scene/world_database.hpp"

namespace cig {
namespace {

using V = glm::dvec3;

// ---- The oracle: its own planes (cross products) and its own point-in-polygon test.

struct OraclePolygon {
  std::vector<V> p;
  V n;  // unit normal, counter-clockwise front
  double d;
};

OraclePolygon oracle_polygon(const Subobject& s, const Polygon& poly) {
  OraclePolygon o;
  for (auto i : poly.indices) o.p.push_back(s.vertices[i]);
  V n(0);
  for (std::size_t k = 1; k + 1 < o.p.size(); ++k) {
    const V a = o.p[k] - o.p[0], b = o.p[k + 1] - o.p[0];
    n += V(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
  }
  o.n = n / std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  o.d = o.n.x * o.p[0].x + o.n.y * o.p[0].y + o.n.z * o.p[0].z;
  return o;
}

double dot3(const V& a, const V& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V cross3(const V& a, const V& b) { return V(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }

// Strictly inside (by `margin` of each edge's length) the convex polygon, x on its plane.
bool inside(const OraclePolygon& o, const V& x, double margin) {
  for (std::size_t k = 0; k < o.p.size(); ++k) {
    const V a = o.p[k], b = o.p[(k + 1) % o.p.size()];
    const V e = b - a;
    const double len = std::sqrt(dot3(e, e));
    if (dot3(cross3(e, x - a), o.n) <= margin * len) return false;
  }
  return true;
}

// Pairs (j drawn after i) where j lies strictly between the eye and a sample point of i.
int order_violations(const Subobject& s, const std::vector<std::uint32_t>& order, const V& eye, double scale,
                     bool debug = false) {
  std::vector<OraclePolygon> polys;
  for (const Polygon& p : s.polygons) polys.push_back(oracle_polygon(s, p));
  std::vector<int> rank(polys.size(), -1);
  for (std::size_t k = 0; k < order.size(); ++k) rank[order[k]] = int(k);
  const double margin = 1e-7 * scale;
  int bad = 0;
  for (std::size_t i = 0; i < polys.size(); ++i) {
    const OraclePolygon& pi = polys[i];
    if (dot3(pi.n, eye) <= pi.d + margin) continue;  // back-facing: culled, never drawn
    V c(0);
    for (const V& q : pi.p) c += q / double(pi.p.size());
    std::vector<V> samples{c};
    for (const V& q : pi.p) samples.push_back(c + 0.8 * (q - c));
    for (const V& q : samples) {
      const V dir = q - eye;
      for (std::size_t j = 0; j < polys.size(); ++j) {
        const OraclePolygon& pj = polys[j];
        if (j == i || dot3(pj.n, eye) <= pj.d + margin) continue;
        const double den = dot3(pj.n, dir);
        if (std::abs(den) < 1e-12) continue;
        const double t = (pj.d - dot3(pj.n, eye)) / den;
        if (!(t > 1e-6 && t < 1 - 1e-6)) continue;
        if (inside(pj, eye + t * dir, margin) && rank[j] > rank[i]) {
          ++bad;
          if (debug && std::getenv("ORACLE_DEBUG")) {
            std::printf("violation: i=%zu rank %d, j=%zu rank %d, t=%g\n", i, rank[i], j, rank[j], t);
            for (auto* pp : {&pi, &pj}) {
              for (const V& v : pp->p) std::printf("  (%.9g %.9g %.9g)", v.x, v.y, v.z);
              std::printf("  n=(%g %g %g) d=%g\n", pp->n.x, pp->n.y, pp->n.z, pp->d);
            }
            for (const V& v : pj.p) std::printf("  j vertex vs i plane: %g\n", dot3(pi.n, v) - pi.d);
            for (const V& v : pi.p) std::printf("  i vertex vs j plane: %g\n", dot3(pj.n, v) - pj.d);
          }
        }
      }
    }
  }
  return bad;
}

// ---- Scenes.

std::string scene_json(const std::vector<nlohmann::json>& list) {
  const nlohmann::json subobjects = list;
  nlohmann::json s = {{"format", "cig-scene"},
                      {"version", 1},
                      {"channels", {{{"name", "c"}, {"fov", 40}}}},
                      {"observer", {{"keyframes", {{{"frame", 0}, {"position", {0, -50, 0}}}}}}},
                      {"objects", {{{"name", "o"}, {"subobjects", subobjects}}}}};
  return s.dump();
}

// n random triangles in a 10 m cube: a soup full of intersections and cycles of "may hide".
nlohmann::json triangle_soup(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-5, 5), small(-2.5, 2.5);
  nlohmann::json vertices = nlohmann::json::array(), polygons = nlohmann::json::array();
  for (int t = 0; t < n; ++t) {
    const V c(u(rng), u(rng), u(rng));
    V a, b, d;
    do {
      a = c + V(small(rng), small(rng), small(rng));
      b = c + V(small(rng), small(rng), small(rng));
      d = c + V(small(rng), small(rng), small(rng));
    } while (std::sqrt(dot3(cross3(b - a, d - a), cross3(b - a, d - a))) < 0.5);
    for (const V& v : {a, b, d}) vertices.push_back({v.x, v.y, v.z});
    polygons.push_back({{"indices", {3 * t, 3 * t + 1, 3 * t + 2}}});
  }
  return {{"name", "soup"}, {"priority_order", "tree"}, {"vertices", vertices}, {"polygons", polygons}};
}

SceneLimits no_cache() {
  SceneLimits l;
  l.priority.cache_dir = "";
  return l;
}

std::vector<std::uint32_t> walk(const Scene& scene, const WorldDatabase& db, const V& eye) {
  std::vector<std::uint32_t> order;
  const Subobject& s = scene.objects[0].subobjects[0];
  if (s.bsp.empty()) {
    for (std::uint32_t i = 0; i < s.polygons.size(); ++i) order.push_back(i);
  } else {
    const PriorityWalkCost cost = walk_priority_tree(s.bsp, db.objects[0].subobjects[0], eye, false, order);
    // Every polygon exactly once; every node visited once; the cost as geometric_processor.hpp
    // derives it: 9 L a node (record, two stack entries pushed and popped), 4 L and 3 M, 2 A a
    // partition test, 1 C a node, 1 L a polygon.
    std::vector<std::uint32_t> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    for (std::uint32_t k = 0; k < sorted.size(); ++k) EXPECT_EQ(sorted[k], k);
    EXPECT_EQ(sorted.size(), s.polygons.size());
    EXPECT_EQ(cost.nodes, s.bsp.size());
    EXPECT_EQ(cost.ops.L, 9 * cost.nodes + 4 * cost.partitions + order.size());
    EXPECT_EQ(cost.ops.C, cost.nodes);
    EXPECT_EQ(cost.ops.M, 3 * cost.partitions);
    EXPECT_EQ(cost.ops.A, 2 * cost.partitions);
    // Farthest first is the same order reversed.
    std::vector<std::uint32_t> back;
    walk_priority_tree(s.bsp, db.objects[0].subobjects[0], eye, true, back);
    EXPECT_TRUE(std::equal(back.rbegin(), back.rend(), order.begin(), order.end()));
  }
  return order;
}

std::vector<V> eyes(unsigned seed, int n, double radius) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  std::vector<V> out;
  for (int k = 0; k < n; ++k) {
    V d(g(rng), g(rng), g(rng));
    out.push_back(d * (radius / std::sqrt(dot3(d, d))));
  }
  return out;
}

TEST(PriorityCompiler, ASoupOfTrianglesIsOrderedFromEveryEye) {
  for (unsigned seed : {1u, 2u, 3u, 4u, 5u, 6u}) {
    const Scene list_order = parse_scene(scene_json({triangle_soup(60, seed)}), "soup.json", [] {
      SceneLimits l = no_cache();
      l.priority.enabled = false;
      return l;
    }());
    const Scene scene = parse_scene(scene_json({triangle_soup(60, seed)}), "soup.json", no_cache());
    const WorldDatabase db = build_world_database(scene);
    const WorldDatabase db0 = build_world_database(list_order);
    ASSERT_EQ(scene.priority.compiled, 1u);
    EXPECT_GT(scene.priority.splits, 0u);  // a soup has cycles only a plane breaks
    int before = 0;
    // Eyes outside the soup and inside it (within the cube, between the triangles).
    std::vector<V> all = eyes(seed, 12, 20);
    for (const V& e : eyes(seed + 100, 8, 3)) all.push_back(e);
    for (const V& e : all) {
      EXPECT_EQ(order_violations(scene.objects[0].subobjects[0], walk(scene, db, e), e, 10, true), 0)
          << "seed " << seed << " eye " << e.x << " " << e.y << " " << e.z;
      before += order_violations(list_order.objects[0].subobjects[0], walk(list_order, db0, e), e, 10);
    }
    EXPECT_GT(before, 0) << "the oracle finds the list order wrong, or the test proves nothing";
  }
}

TEST(PriorityCompiler, InterpenetratingObjectsGetOneTree) {
  // Two soups in two objects whose spheres overlap (one turned and moved), and a third far away.
  nlohmann::json s = nlohmann::json::parse(scene_json({triangle_soup(30, 21)}));
  nlohmann::json b = {{"name", "b"}, {"position", {3, 1, 0}}, {"heading", 40}, {"subobjects", {triangle_soup(30, 22)}}};
  nlohmann::json far = {{"name", "far"}, {"position", {500, 0, 0}}, {"subobjects", {triangle_soup(10, 23)}}};
  b["subobjects"] = nlohmann::json::array({triangle_soup(30, 22)});
  far["subobjects"] = nlohmann::json::array({triangle_soup(10, 23)});
  s["objects"].push_back(b);
  s["objects"].push_back(far);
  const Scene scene = parse_scene(s.dump(), "group.json", no_cache());
  EXPECT_EQ(scene.priority.groups, 1u);
  EXPECT_EQ(scene.priority.grouped_objects, 2u);
  ASSERT_EQ(scene.objects.size(), 2u);
  EXPECT_EQ(scene.objects[0].name, "o+b");
  ASSERT_EQ(scene.objects[0].subobjects.size(), 1u);
  EXPECT_EQ(scene.objects[1].name, "far");
  const WorldDatabase db = build_world_database(scene);
  for (const V& e : eyes(31, 10, 25)) {
    const V eye_object = e;  // the group sits at the first member's position, the origin, unturned
    EXPECT_EQ(order_violations(scene.objects[0].subobjects[0], walk(scene, db, e), eye_object, 12), 0);
  }
}

TEST(PriorityCompiler, AValidOrderIsKeptAndAnInlineListIsNotCompiled) {
  // A closed box: convex, every order valid; no tree, no split, the list as written.
  const nlohmann::json box = {
      {"name", "box"},
      {"priority_order", "tree"},
      {"vertices", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}},
      {"polygons",
       {{{"indices", {3, 2, 1, 0}}},
        {{"indices", {4, 5, 6, 7}}},
        {{"indices", {0, 1, 5, 4}}},
        {{"indices", {1, 2, 6, 5}}},
        {{"indices", {2, 3, 7, 6}}},
        {{"indices", {3, 0, 4, 7}}}}}};
  const Scene s = parse_scene(scene_json({box}), "box.json", no_cache());
  EXPECT_EQ(s.priority.ordered, 1u);
  EXPECT_EQ(s.priority.compiled, 0u);
  EXPECT_TRUE(s.objects[0].subobjects[0].bsp.empty());
  // The soup as an inline list without "priority_order": kept, and counted as not valid.
  nlohmann::json soup = triangle_soup(30, 7);
  soup.erase("priority_order");
  const Scene k = parse_scene(scene_json({soup}), "soup.json", no_cache());
  EXPECT_EQ(k.priority.kept_not_valid, 1u);
  EXPECT_TRUE(k.objects[0].subobjects[0].bsp.empty());
}

TEST(PriorityCompiler, ADecalStaysBeforeTheSurfaceItLiesOn) {
  // A runway (the big square) with a marking on its plane listed first, and two crossing walls
  // that force a tree: from above, the marking must still come before the runway.
  const nlohmann::json sub = {{"name", "apron"},
                              {"priority_order", "tree"},
                              {"vertices",
                               {{-1, -1, 0},
                                {1, -1, 0},
                                {1, 1, 0},
                                {-1, 1, 0},  // marking
                                {-9, -9, 0},
                                {9, -9, 0},
                                {9, 9, 0},
                                {-9, 9, 0},  // runway
                                {-4, 0, 0.1},
                                {4, 0, 0.1},
                                {4, 0, 3},
                                {-4, 0, 3},  // wall along x (two-sided: two polygons)
                                {0, -4, 0.1},
                                {0, 4, 0.1},
                                {0, 4, 3},
                                {0, -4, 3}}},  // wall along y
                              {"polygons",
                               {{{"indices", {0, 1, 2, 3}}},
                                {{"indices", {4, 5, 6, 7}}},
                                {{"indices", {8, 9, 10, 11}}},
                                {{"indices", {11, 10, 9, 8}}},
                                {{"indices", {12, 13, 14, 15}}},
                                {{"indices", {15, 14, 13, 12}}}}}};
  const Scene s = parse_scene(scene_json({sub}), "apron.json", no_cache());
  ASSERT_EQ(s.priority.compiled, 1u);
  const WorldDatabase db = build_world_database(s);
  const Subobject& so = s.objects[0].subobjects[0];
  for (const V& eye : {V(5, 6, 20), V(-7, -3, 4), V(0.5, 0.5, 30)}) {
    const std::vector<std::uint32_t> order = walk(s, db, eye);
    // The marking's pieces (colour is the same; find them by lying within |x|, |y| <= 1 at z = 0).
    int last_marking = -1, first_runway = int(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
      const Polygon& p = so.polygons[order[k]];
      bool small = true, flat = true;
      for (auto i : p.indices) {
        small = small && std::abs(so.vertices[i].x) <= 1 + 1e-9 && std::abs(so.vertices[i].y) <= 1 + 1e-9;
        flat = flat && so.vertices[i].z == 0;
      }
      if (flat && small) last_marking = std::max(last_marking, int(k));
      if (flat && !small) first_runway = std::min(first_runway, int(k));
    }
    EXPECT_LT(last_marking, first_runway) << "eye " << eye.x << " " << eye.y << " " << eye.z;
    EXPECT_EQ(order_violations(so, order, eye, 10), 0);
  }
}

TEST(PriorityCompiler, TheCacheGivesTheSameTreeAndSurvivesADamagedFile) {
  const std::string dir = ::testing::TempDir() + "cig_priority_cache_test";
  std::filesystem::remove_all(dir);
  SceneLimits l;
  l.priority.cache_dir = dir;
  const std::string text = scene_json({triangle_soup(40, 11)});
  const Scene first = parse_scene(text, "soup.json", l);
  EXPECT_EQ(first.priority.cache_writes, 1u);
  const Scene second = parse_scene(text, "soup.json", l);
  EXPECT_EQ(second.priority.cache_hits, 1u);
  auto same = [](const Subobject& a, const Subobject& b) {
    if (a.vertices != b.vertices || a.polygons.size() != b.polygons.size() || a.bsp.size() != b.bsp.size())
      return false;
    for (std::size_t k = 0; k < a.polygons.size(); ++k)
      if (a.polygons[k].indices != b.polygons[k].indices) return false;
    for (std::size_t k = 0; k < a.bsp.size(); ++k)
      if (a.bsp[k].first != b.bsp[k].first || a.bsp[k].count != b.bsp[k].count || a.bsp[k].front != b.bsp[k].front ||
          a.bsp[k].back != b.bsp[k].back || a.bsp[k].next != b.bsp[k].next)
        return false;
    return true;
  };
  EXPECT_TRUE(same(first.objects[0].subobjects[0], second.objects[0].subobjects[0]));
  // Damage every cached file: one byte flipped, then cut short. Each load recompiles.
  for (int damage = 0; damage < 2; ++damage) {
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
      std::string bytes;
      {
        std::ifstream in(e.path(), std::ios::binary);
        std::stringstream ss;
        ss << in.rdbuf();
        bytes = ss.str();
      }
      if (damage == 0) bytes[bytes.size() / 2] = char(bytes[bytes.size() / 2] ^ 0x5a);
      else bytes.resize(bytes.size() / 3);
      std::ofstream(e.path(), std::ios::binary | std::ios::trunc) << bytes;
    }
    const Scene again = parse_scene(text, "soup.json", l);
    EXPECT_EQ(again.priority.cache_hits, 0u);
    EXPECT_EQ(again.priority.compiled, 1u);
    EXPECT_TRUE(same(first.objects[0].subobjects[0], again.objects[0].subobjects[0]));
  }
  std::filesystem::remove_all(dir);
}

TEST(PriorityCompiler, GrowthBeyondTheLimitKeepsTheListAndSaysSo) {
  SceneLimits l = no_cache();
  l.priority.max_growth = 1;
  l.priority.split_allowance = 0;
  const Scene s = parse_scene(scene_json({triangle_soup(60, 5)}), "soup.json", l);
  EXPECT_EQ(s.priority.too_large, 1u);
  EXPECT_EQ(s.priority.compiled, 0u);
  EXPECT_TRUE(s.objects[0].subobjects[0].bsp.empty());
  EXPECT_EQ(s.objects[0].subobjects[0].polygons.size(), 60u);
}

TEST(PriorityCompiler, RealModelsAreOrderedFromEveryEye) {
  const std::string models = "/usr/share/assimp/models/";
  if (!std::filesystem::exists(models + "3DS/fels.3ds"))
    GTEST_SKIP() << "assimp-testmodels is not installed (tools/deps.sh installs it)";
  for (const char* file : {"3DS/fels.3ds", "LWO/LWO2/hierarchy.lwo"}) {
    const nlohmann::json sub = {{"name", "m"}, {"model", models + file}};
    const Scene s = parse_scene(scene_json({sub}), "model.json", no_cache());
    ASSERT_EQ(s.priority.compiled, 1u) << file;
    const WorldDatabase db = build_world_database(s);
    for (const V& e : eyes(17, 6, 12))
      EXPECT_EQ(order_violations(s.objects[0].subobjects[0], walk(s, db, e), e, 5), 0) << file;
  }
}

}  // namespace
}  // namespace cig
