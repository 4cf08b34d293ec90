#include "generator/frame_governor.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace cig {

ListWork list_work(const WorldDatabase& db, const PriorityList& list, const glm::dvec3& eye) {
  ListWork w;
  for (const PriorityEntry& e : list.objects) {
    const WorldObject& o = db.objects[e.object];
    for (const std::uint32_t si : list.run(e)) {
      const WorldSubobject& s = o.subobjects[si];
      const std::size_t polygons = s.face_normal.size();
      for (std::size_t p = 0; p < polygons; ++p) {
        const std::uint64_t corners = s.first_corner[p + 1] - s.first_corner[p];
        w.corners += corners;
        if (glm::dot(s.face_normal[p], eye) > s.face_offset[p]) w.front_corners += corners;  // the eye on its front
      }
    }
    if (e.lights) {
      w.corners += o.light_positions.size();
      w.front_corners += o.light_positions.size();
    }
  }
  return w;
}

FrameGovernor::FrameGovernor(double budget_ms, bool raster_governs_itself, int channels)
    : budget_ms_(budget_ms),
      raster_governs_itself_(raster_governs_itself),
      costs_(std::size_t(channels)),
      history_(std::size_t(channels)) {}

double FrameGovernor::predict_ms(int channel, std::uint64_t objects_kept, const ListWork& w) const {
  const GovernorCosts& c = costs_[std::size_t(channel)];
  const double front = double(w.front_corners);
  const double raster = raster_governs_itself_ ? 0.0 : double(w.corners) * c.raster_per_corner;
  return std::max({double(objects_kept) * c.a_per_object, front * c.b_per_front_corner,
                   front * c.edges_per_front_corner, raster}) *
         1e-6;
}

PriorityList FrameGovernor::choose(int channel, ChannelView view, const Manage& manage, const WorldDatabase& db,
                                   GovernorDecision& d, SceneManagerStats* final_stats) const {
  SceneManagerStats stats;
  PriorityList list = manage(view, stats);
  if (final_stats) *final_stats = stats;
  d.range = d.range_ungoverned = view.range;
  d.headroom = headroom_;
  d.objects_kept = stats.cull.objects_kept;
  d.work = list_work(db, list, view.eye);
  d.predicted_ms = d.predicted_ungoverned_ms = predict_ms(channel, d.objects_kept, d.work);
  const double target = target_ms();
  if (d.predicted_ms <= target) return list;
  // Bisection on the range, from the near plane to the view's (the work grows with the range).
  double lo = view.near, hi = std::isfinite(view.range) ? view.range : 1e7;
  for (int step = 0; step < 30 && hi - lo > 1.0; ++step) {
    ChannelView v = view;
    v.range = 0.5 * (lo + hi);
    SceneManagerStats s;
    const PriorityList l = manage(v, s);
    (predict_ms(channel, s.cull.objects_kept, list_work(db, l, view.eye)) <= target ? lo : hi) = v.range;
  }
  view.range = lo;
  SceneManagerStats s;
  PriorityList cut = manage(view, s);
  if (final_stats) *final_stats = s;
  d.range = lo;
  d.range_cut = true;
  d.objects_cut = list.objects.size() - std::min(list.objects.size(), cut.objects.size());
  d.objects_kept = s.cull.objects_kept;
  d.work = list_work(db, cut, view.eye);
  d.predicted_ms = predict_ms(channel, d.objects_kept, d.work);
  return cut;
}

void FrameGovernor::learn(int channel, const GovernorDecision& d, double a_ms, double b_ms, double edges_ms,
                          double raster_ms) {
  const double modelled = std::max({a_ms, b_ms, edges_ms, raster_governs_itself_ ? 0.0 : raster_ms});
  if (d.predicted_ms > 0) headroom_ = std::max(headroom_, modelled / d.predicted_ms - 1);
  GovernorCosts& c = costs_[std::size_t(channel)];
  GovernorCosts seen = c;  // this frame's own costs, where it had the work to show them
  if (d.objects_kept > 0) seen.a_per_object = a_ms * 1e6 / double(d.objects_kept);
  if (d.work.front_corners > 0) {
    seen.b_per_front_corner = b_ms * 1e6 / double(d.work.front_corners);
    seen.edges_per_front_corner = edges_ms * 1e6 / double(d.work.front_corners);
  }
  if (d.work.corners > 0) seen.raster_per_corner = raster_ms * 1e6 / double(d.work.corners);
  std::deque<GovernorCosts>& h = history_[std::size_t(channel)];
  h.push_back(seen);
  if (h.size() > kWindow) h.pop_front();
  c = GovernorCosts{0, 0, 0, 0};
  for (const GovernorCosts& f : h) {
    c.a_per_object = std::max(c.a_per_object, f.a_per_object);
    c.b_per_front_corner = std::max(c.b_per_front_corner, f.b_per_front_corner);
    c.edges_per_front_corner = std::max(c.edges_per_front_corner, f.edges_per_front_corner);
    c.raster_per_corner = std::max(c.raster_per_corner, f.raster_per_corner);
  }
}

namespace {
nlohmann::ordered_json metres(double range) {
  return std::isfinite(range) ? nlohmann::ordered_json(range) : nlohmann::ordered_json("none");
}
double metres_of(const nlohmann::ordered_json& j) { return j.is_number() ? j.get<double>() : HUGE_VAL; }
}  // namespace

nlohmann::ordered_json FrameGovernor::report(const GovernorDecision& d) {
  return {{"predicted_ungoverned_ms", d.predicted_ungoverned_ms},
          {"predicted_ms", d.predicted_ms},
          {"range_cut", d.range_cut},
          {"range", metres(d.range)},
          {"range_ungoverned", metres(d.range_ungoverned)},
          {"objects_cut", d.objects_cut},
          {"objects_kept", d.objects_kept},
          {"corners", d.work.corners},
          {"front_corners", d.work.front_corners},
          {"headroom", d.headroom}};
}

GovernorDecision FrameGovernor::decision_of(const nlohmann::ordered_json& r) {
  GovernorDecision d;
  d.predicted_ms = r["predicted_ms"].get<double>();
  d.predicted_ungoverned_ms = r["predicted_ungoverned_ms"].get<double>();
  d.range_cut = r["range_cut"].get<bool>();
  d.range = metres_of(r["range"]);
  d.range_ungoverned = metres_of(r["range_ungoverned"]);
  d.objects_cut = r["objects_cut"].get<std::uint64_t>();
  d.objects_kept = r["objects_kept"].get<std::uint64_t>();
  d.work.corners = r["corners"].get<std::uint64_t>();
  d.work.front_corners = r["front_corners"].get<std::uint64_t>();
  d.headroom = r["headroom"].get<double>();
  return d;
}

}  // namespace cig
