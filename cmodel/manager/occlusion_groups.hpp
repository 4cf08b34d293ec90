// Occlusion groups of seed 000 (SPEC A): the preliminary sorting unit marks every pair of visible
// objects whose bounding spheres overlap, |c_i - c_j| < R_i + R_j, as occluding each other; the
// groups are the connected components of that relation (an object in no pair is a group of one,
// and keeps its modeller's subobject list). Only objects of one priority layer group: layers are
// drawn in their own order whatever the spheres do.
//
// Two ways to find them, the same partition:
//   * groups_pairwise: the seed's loop over all pairs i < j, the counted model (N(N-1)/2 tests);
//   * groups_by_sweep: sort by x - R, sweep along x keeping the spheres whose x extent is still
//     open, test only those pairs; for scenes of 10^5 objects.
//
// Order between groups. The seed sorts by the distance to the centre, which is not a visibility
// order for spheres of different radii (a large sphere whose centre is farther can still hide a
// small one behind it). The key here is the power of the eye, p = |c|^2 - R^2: for two disjoint
// spheres A, B the radical plane {x : pow_A(x) = pow_B(x)} separates them (inside A, pow_A < 0 <
// pow_B), a ray from the eye crosses it at most once, so if the eye is on A's side (p_A < p_B) no
// ray meets B before A: sorting by p is a valid front-to-back order for non-overlapping spheres
// (verif/unit/test_occlusion_groups.cpp checks it with rays). A group is keyed by the least power
// of its members; two groups may hide each other in turn (no order exists for them as units), and
// the least power puts first the group holding the sphere that can hide any other.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace cig {

struct GroupSphere {
  glm::dvec3 centre;  // eye coordinates
  double radius = 0;
  int layer = 0;
};

// The eye's power with respect to the sphere: |c|^2 - R^2 (negative when the eye is inside).
double eye_power(const GroupSphere& s);

// Group of each sphere, numbered 0..count-1 in order of each group's first sphere.
struct SphereGroups {
  std::vector<int> group;
  int count = 0;
  std::uint64_t pair_tests = 0;  // sphere pairs compared
};

SphereGroups groups_pairwise(const std::vector<GroupSphere>& spheres);
SphereGroups groups_by_sweep(const std::vector<GroupSphere>& spheres);

// A k-way merge of priority lists by the distance of their entries (the seed's two-list merge of
// DI and DJ, generalised): each list keeps its own order; at each step the list whose next entry
// is nearest (ties: the earlier list) gives that entry. Returns (list, index in list) pairs.
struct MergeItem {
  double distance;
  std::uint32_t value;
};
std::vector<std::pair<std::uint32_t, std::uint32_t>> merge_by_distance(
    const std::vector<std::vector<MergeItem>>& lists);

}  // namespace cig
