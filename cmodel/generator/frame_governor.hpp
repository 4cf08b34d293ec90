// The frame governor's visibility range (`--budget-ms`, studies/frame_timing.hpp's stages): before
// stage B runs, predict each stage's time for the channel's priority list and, when the frame would
// be over budget, shorten the visibility range (ChannelView::range: the scene manager and seed 003's
// quadtree cull objects wholly deeper) to the longest that fits. The cheaper degradation, the
// segment processor's overload threshold, is the engine's (timing/segment_prediction.hpp); this one
// cuts what the threshold cannot: stages A and B and the edge generator.
//
// Prediction: each stage's time per unit of work, learned from the channel's last frames (frame to
// frame coherence: the same eye a frame later sees nearly the same mix), times this frame's work:
//   A            objects seed 003's quadtree kept (SceneManagerStats::cull.objects_kept)
//   B and edges  corners of the listed polygons that face the eye (processor 1's back-face test,
//                one dot product a polygon, made ahead on the list: processor 2 and the edge
//                generator see only those), and the light points
//   raster       every listed corner (engines without a governor of their own; none for the
//                segment processor, whose threshold governs its passes)
// Each cost is the largest of the channel's last 32 frames' (a peak hold: one cheap frame does not
// invite a late one). Before the first frame: B and the edge generator at seed 001's 10 us per
// corner (an edge each), A and raster unknown (0). The range is chosen for budget / (1 + headroom),
// headroom = the largest under-prediction seen so far on any channel, at least 20% (A: a stated
// margin for the first frames). The range is found by bisection on the manager's own runs.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <vector>

#include <nlohmann/json.hpp>

#include "manager/scene_manager.hpp"

namespace cig {

// The work a priority list gives stages B and the raster engine.
struct ListWork {
  std::uint64_t corners = 0;        // every listed polygon's corners, and the light points
  std::uint64_t front_corners = 0;  // of those, the polygons facing the eye, and the light points
};
ListWork list_work(const WorldDatabase& db, const PriorityList& list, const glm::dvec3& eye);

struct GovernorCosts {  // ns per unit of work
  double a_per_object = 0, b_per_front_corner = 10000, edges_per_front_corner = 10000, raster_per_corner = 0;
};

// What the governor decided for one channel's frame.
struct GovernorDecision {
  double predicted_ms = 0, predicted_ungoverned_ms = 0;
  double range = 0, range_ungoverned = 0;  // the visibility range (m) used, and the scene's
  std::uint64_t objects_kept = 0, objects_cut = 0;
  ListWork work;
  bool range_cut = false;
  double headroom = 0;  // the governor's, when the range was chosen
};

class FrameGovernor {
 public:
  FrameGovernor(double budget_ms, bool raster_governs_itself, int channels);

  // The longest range (up to the view's) whose predicted stages fit; `manage` runs the scene
  // manager for a view (the governor calls it with shorter ranges).
  using Manage = std::function<PriorityList(const ChannelView&, SceneManagerStats&)>;
  // `stats`, when given: the scene manager's figures for the list returned.
  PriorityList choose(int channel, ChannelView view, const Manage& manage, const WorldDatabase& db, GovernorDecision& d,
                      SceneManagerStats* stats = nullptr) const;

  // After the frame: the stages' modelled ms for the work the decision let through.
  void learn(int channel, const GovernorDecision& d, double a_ms, double b_ms, double edges_ms, double raster_ms);

  static nlohmann::ordered_json report(const GovernorDecision& d);
  static GovernorDecision decision_of(const nlohmann::ordered_json& report);  // what report() wrote

 private:
  double predict_ms(int channel, std::uint64_t objects_kept, const ListWork& w) const;
  double target_ms() const { return budget_ms_ / (1 + headroom_); }

  double budget_ms_;
  bool raster_governs_itself_;
  // Per channel: the costs the prediction uses (the peak of the last kWindow frames') and those
  // frames' own.
  static constexpr std::size_t kWindow = 32;
  std::vector<GovernorCosts> costs_;
  std::vector<std::deque<GovernorCosts>> history_;
  double headroom_ = 0.2;  // A: the margin before any under-prediction is seen (docs/timing.md)
};

}  // namespace cig
