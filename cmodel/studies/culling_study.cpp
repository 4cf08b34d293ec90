#include "studies/culling_study.hpp"

#include <algorithm>
#include <iterator>
#include <limits>

#include "common/timing.hpp"
#include "manager/scene_manager.hpp"
#include "scene/world_database.hpp"

namespace cig {

namespace {

// One method on one channel: the best of `repeat` runs, and its visible set.
std::vector<std::uint32_t> run_method(const WorldDatabase& db, const ChannelView& view, const ManagerOptions& options,
                                      int repeat, CullingRow& row) {
  std::vector<std::uint32_t> ids;
  double best = std::numeric_limits<double>::infinity();
  SceneManagerStats kept;
  for (int r = 0; r < repeat; ++r) {
    SceneManagerStats st;
    const auto t0 = Clock::now();
    ids = potentially_visible(db, view, options, st);
    best = std::min(best, ms_since(t0));
    kept = st;
  }
  row.ms += best;
  row.nodes_visited += kept.cull.nodes_visited;
  row.nodes_kept += kept.cull.nodes_kept;
  row.objects_kept += options.tree ? kept.cull.objects_kept : db.objects.size();
  row.visible += ids.size();
  return ids;
}

}  // namespace

CullingStudy run_culling_study(const Scene& scene, const CullingStudyOptions& o) {
  const WorldDatabase db = build_world_database(scene);
  const SceneQuadtree tree(db);
  CullingStudy s;
  s.objects = db.objects.size();
  s.nodes = tree.node_count();
  for (CullMethod m :
       {CullMethod::kLineOfSight, CullMethod::kProjection, CullMethod::kHierarchical, CullMethod::kBruteForce})
    s.rows.push_back({m});
  for (int frame = o.first_frame; frame <= o.last_frame; ++frame)
    for (int c = 0; c < int(scene.channels.size()); ++c, ++s.channels) {
      const ChannelView view = make_channel_view(scene, frame, c);
      std::vector<std::uint32_t> want;  // brute force (the last row) runs first: the others' truth
      for (std::size_t k = 0; k < s.rows.size(); ++k) {
        CullingRow& row = s.rows[(k + s.rows.size() - 1) % s.rows.size()];
        ManagerOptions mo;
        mo.tree = row.method == CullMethod::kBruteForce ? nullptr : &tree;
        mo.culling = {row.method, o.near_distance, o.far_distance};
        const std::vector<std::uint32_t> got = run_method(db, view, mo, o.repeat, row);
        if (row.method == CullMethod::kBruteForce) want = got;
        std::vector<std::uint32_t> missing, extra;
        std::set_difference(want.begin(), want.end(), got.begin(), got.end(), std::back_inserter(missing));
        std::set_difference(got.begin(), got.end(), want.begin(), want.end(), std::back_inserter(extra));
        row.false_negatives += missing.size();
        row.false_positives += extra.size();
      }
    }
  return s;
}

}  // namespace cig
