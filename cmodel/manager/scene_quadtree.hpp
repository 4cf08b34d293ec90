// Object-oriented quadtree and line-of-sight culling of seed 003 (SPEC A): the scene's objects
// organised by their place on the ground, so that a channel's visibility test visits the part of
// the world the view can see instead of every object.
//
// Tree. The AABB of every object's bounding sphere spans the world; the root is that box, split
// recursively into four in x and y (the ground plane; z is up), down to nodes of at most
// kLeafObjects objects or kMaxDepth levels. An object that straddles a split stays at the smallest
// node whose box holds its sphere's box (a loose quadtree: objects live in inner nodes too), so
// every object is referenced once. Every node keeps the AABB of the spheres below it (tight) and
// the bounding sphere of that AABB.
//
// Culling (per channel; a node's objects are then tested one by one with the scene manager's
// sphere test, so the visible set is exactly the brute-force one whenever the node tests are
// conservative, which they are: a node is rejected only when a volume holding all its spheres lies
// wholly outside one plane of the viewing pyramid):
//   * kLineOfSight (seed 003, Fig. 2-3): by the node's distance D from the eye, the sphere test
//     for D <= D_near (cone area V-I), the sphere then the AABB for D_near < D < D_far (V-II), the
//     AABB for D >= D_far (V-III);
//   * kHierarchical (Table 1's method 3): sphere and AABB at every node;
//   * kProjection (Table 1's method 2, geometric projection with reduced dimension): the node's
//     box projected onto the ground plane against the footprint of the pyramid (the convex hull of
//     the apex and the pyramid's corners at the world's farthest distance, projected). The scene
//     manager keeps a sphere that is not wholly outside any one plane, which is more than the
//     spheres meeting the pyramid; such a sphere's centre lies in the pyramid with every plane
//     moved out by its radius r, which is inside the pyramid moved back along the line of sight
//     by r sqrt(1 + t^2) / t (t = tan(fov/2)). So each node is tested against the footprint of the
//     pyramid moved back for the largest radius below it (rounded up to a power of two: one hull
//     per octave and channel);
//   * kBruteForce: no tree, every object's sphere (the baseline and the ground truth).
// A node wholly inside every plane is accepted with its subtree without further tests (all
// methods). A scene's visibility range (Scene::range) is a sixth plane, z <= range, for every
// method (the projection truncates its footprint there).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "manager/channel_view.hpp"
#include "scene/world_database.hpp"

namespace cig {

enum class CullMethod { kLineOfSight, kHierarchical, kProjection, kBruteForce };
CullMethod parse_cull_method(const std::string& text);  // InputError naming --culling
const char* cull_method_name(CullMethod m);

struct CullSettings {
  CullMethod method = CullMethod::kLineOfSight;
  double near_distance = 2000;  // D_near, m
  double far_distance = 8000;   // D_far, m
};

struct CullStats {
  std::uint64_t nodes_visited = 0, nodes_kept = 0, objects_kept = 0;
  double ms = 0;
};

class SceneQuadtree {
 public:
  static constexpr int kLeafObjects = 16;
  static constexpr int kMaxDepth = 14;

  explicit SceneQuadtree(const WorldDatabase& db);

  // The objects whose node survives the culling, in the tree's order (depth first).
  std::vector<std::uint32_t> cull(const ChannelView& view, const CullSettings& settings, CullStats& stats) const;

  std::size_t node_count() const { return nodes_.size(); }

 private:
  struct Node {
    glm::dvec3 lo{0}, hi{0};  // AABB of the spheres below
    glm::dvec3 centre{0};     // bounding sphere of that AABB
    double radius = 0;
    double largest_object = 0;  // the largest object radius below (the projection's offset)
    std::int32_t child[4] = {-1, -1, -1, -1};
    std::uint32_t first = 0, count = 0;  // objects held here: objects_[first, first + count)
    std::uint32_t subtree_end = 0;       // objects_ index after the subtree's last object
    std::uint32_t node_end = 0;          // nodes_ index after the subtree's last node (preorder)
  };
  std::int32_t build(std::vector<std::uint32_t>& ids, glm::dvec2 lo, glm::dvec2 hi, int depth);

  const WorldDatabase& db_;
  std::vector<Node> nodes_;
  std::vector<std::uint32_t> objects_;  // by node, depth first (a subtree's objects are contiguous)
};

}  // namespace cig
