// Seed 000's loading of the rendering channels (Nc): one channel's priority list cut into N
// disjoint lists, each a contiguous slice of the priority order, for N rendering pipelines that
// work in parallel; the video stage merges their images by that order (RasterEngine::render_parts).
//
// The seed gives each pipeline whole groups ("mixing the priority lists ... into the groups of
// single neighbouring objects" when there are fewer pipelines than groups). Here the cuts balance
// the pipelines' polygons: cut k goes to the group boundary nearest the point where k/N of the
// polygons lie before it, when that boundary is within an eighth of a share of it; a group too
// large for that is cut between two of its subobjects. Any cut of the priority order gives the
// same image, so the rule only decides the balance.
#pragma once

#include <cstdint>
#include <vector>

#include "manager/scene_manager.hpp"
#include "scene/world_database.hpp"

namespace cig {

struct PipelineLoad {
  std::vector<PriorityList> lists;       // one per pipeline, in priority order
  std::vector<std::uint64_t> polygons;   // the database polygons of each list
  std::uint64_t cuts_inside_groups = 0;  // cuts that fell between two subobjects of one group
};

// pipelines >= 1; a list with fewer subobjects than pipelines leaves some lists empty.
PipelineLoad load_pipelines(const PriorityList& list, const WorldDatabase& db, int pipelines);

// max / mean of the counts (1 when all are equal or all zero).
double load_balance(const std::vector<std::uint64_t>& counts);

}  // namespace cig
