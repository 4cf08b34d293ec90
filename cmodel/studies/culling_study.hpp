// Seed 003's Table 1 reproduced (SPEC A): the scene quadtree's culling methods (line of sight, the
// hierarchical sphere-and-box test, the ground-plane projection) against brute force, over a range
// of frames and every channel. The methods themselves are the scene manager's data path
// (manager/scene_quadtree.hpp); this study only runs each one, times it and compares its visible
// set with brute force's, which is the ground truth (a false negative is a visible object lost).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "manager/scene_quadtree.hpp"
#include "scene/scene.hpp"

namespace cig {

struct CullingRow {
  CullMethod method = CullMethod::kBruteForce;
  std::uint64_t nodes_visited = 0, nodes_kept = 0, objects_kept = 0, visible = 0, false_negatives = 0,
                false_positives = 0;
  double ms = 0;  // sum over channels of the best time (tree walk and the kept objects' sphere tests)
};

struct CullingStudyOptions {
  int first_frame = 0, last_frame = 0;               // inclusive, already checked against the scene
  double near_distance = 2000, far_distance = 8000;  // D_near <= D_far, m
  int repeat = 3;                                    // time each channel this many times, keep the best
};

struct CullingStudy {
  std::vector<CullingRow> rows;  // line of sight, projection, hierarchical, brute force
  long channels = 0;             // channel images: frames x channels
  std::size_t objects = 0, nodes = 0;
};

CullingStudy run_culling_study(const Scene& scene, const CullingStudyOptions& o);

}  // namespace cig
