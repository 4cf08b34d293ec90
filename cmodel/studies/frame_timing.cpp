#include "studies/frame_timing.hpp"

#include <algorithm>
#include <cmath>

#include "studies/operation_counts.hpp"

namespace cig {

namespace {

double number_at(const nlohmann::ordered_json& j, const char* key, double otherwise = 0) {
  return j.is_object() && j.contains(key) && j[key].is_number() ? j[key].get<double>() : otherwise;
}

// Stage A: seed 000's counted scene manager for the channel's objects (operation_counts.hpp).
double manager_ms(const nlohmann::ordered_json& m, const MachineTimingParams& p) {
  // The objects the host sends: those seed 003's quadtree kept, or every one without it.
  const nlohmann::ordered_json& culling = m.value("culling", nlohmann::ordered_json::object());
  const bool tree = culling.value("method", std::string()) != "brute-force";
  const double objects = tree ? number_at(culling, "objects_kept") : number_at(m, "objects");
  const double visible = number_at(m, "objects_visible");
  if (objects <= 0) return 0;
  ManagerStructure s;
  s.objects = std::uint64_t(objects);
  s.occluded = std::min<std::uint64_t>(
      s.objects, std::uint64_t(number_at(m.value("occlusion_groups", nlohmann::ordered_json::object()),
                                         "objects_in_groups_of_2_or_more")));
  const double subobjects = number_at(m, "subobjects_tested");
  s.planes = std::uint32_t(std::max(1.0, std::round(subobjects / std::max(1.0, visible))));
  s.points = p.object_points;
  CapacityQuestion q;
  q.clock_mhz = p.manager_clock_mhz;
  return frame_cycles(q, s) / (p.manager_clock_mhz * 1e3);
}

const char* slowest_stage(const StageTimes& s) {
  const char* name = "A";
  double t = s.a_ms;
  if (s.b_ms > t) name = "B", t = s.b_ms;
  if (s.raster_ms > t) name = "raster", t = s.raster_ms;
  if (s.video_ms > t) name = "video";
  return name;
}

}  // namespace

ChannelTiming time_channel(const nlohmann::ordered_json& r, int raster, const MachineTimingParams& p) {
  ChannelTiming c;
  c.channel = int(number_at(r, "channel"));
  const nlohmann::ordered_json empty = nlohmann::ordered_json::object();
  const nlohmann::ordered_json& geometry = r.contains("geometry") ? r["geometry"] : empty;
  const nlohmann::ordered_json& rast = r.contains("raster") ? r["raster"] : empty;
  c.stages.a_ms = manager_ms(r.contains("scene_manager") ? r["scene_manager"] : empty, p);
  c.geometry_ms = number_at(geometry.value("timing", empty), "ms");
  if (rast.contains("cycle_model")) {  // the segment processor (timing/segment_cycle_model.hpp)
    const auto& cm = rast["cycle_model"];
    c.edge_generator_ms = number_at(cm, "edge_generator_ms");
    c.stages.raster_ms = number_at(cm, "back_ms");
    for (const auto& f : cm["fields"]) c.stages.video_ms += number_at(f, "video_busy_ms");
    c.underrun_lines = (long long)number_at(cm, "underrun_lines");
  } else {
    c.stages.raster_ms = number_at(rast, "hardware_ms");
    c.stages.video_ms = double(raster) * double(raster) * p.video_pixel_ns * 1e-6;
  }
  c.stages.b_ms = std::max(c.geometry_ms, c.edge_generator_ms);
  const StageTimes& s = c.stages;
  c.frame_ms = std::max({s.a_ms, s.b_ms, s.raster_ms, s.video_ms});
  c.transport_ms = s.a_ms + s.b_ms + s.raster_ms + s.video_ms;
  c.limiting = slowest_stage(s);
  return c;
}

FrameTiming time_frame(int frame, const std::vector<ChannelTiming>& channels, const MachineTimingParams& p) {
  FrameTiming t;
  t.frame = frame;
  t.channels = channels;
  for (const ChannelTiming& c : channels) {
    if (c.frame_ms >= t.frame_ms) {
      t.frame_ms = c.frame_ms;
      t.limiting = c.limiting;
    }
    t.transport_ms = std::max(t.transport_ms, c.transport_ms);
    t.underrun_lines += c.underrun_lines;
  }
  t.over_budget = t.frame_ms > p.budget_ms || t.underrun_lines > 0;
  return t;
}

nlohmann::ordered_json frame_timing_json(const FrameTiming& t) {
  nlohmann::ordered_json channels = nlohmann::ordered_json::array();
  for (const ChannelTiming& c : t.channels)
    channels.push_back({{"channel", c.channel},
                        {"a_ms", c.stages.a_ms},
                        {"b_ms", c.stages.b_ms},
                        {"geometry_ms", c.geometry_ms},
                        {"edge_generator_ms", c.edge_generator_ms},
                        {"raster_ms", c.stages.raster_ms},
                        {"video_ms", c.stages.video_ms},
                        {"limiting", c.limiting},
                        {"frame_ms", c.frame_ms},
                        {"transport_ms", c.transport_ms},
                        {"underrun_lines", c.underrun_lines}});
  return {{"frame", t.frame},
          {"frame_ms", t.frame_ms},
          {"transport_ms", t.transport_ms},
          {"limiting", t.limiting},
          {"underrun_lines", t.underrun_lines},
          {"over_budget", t.over_budget},
          {"channels", channels}};
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const double rank = std::ceil(p / 100.0 * double(v.size()));
  const std::size_t k = std::size_t(std::clamp(rank, 1.0, double(v.size()))) - 1;
  return v[k];
}

}  // namespace cig
