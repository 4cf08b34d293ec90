// The whole machine in time: each stage's modelled time for a channel's frame, read from the
// image generator's channel report (what the stages counted and their own time models put there),
// combined as a frame-level pipeline. Each stage works on its own frame (stage A on frame k+3,
// B on k+2, the raster engine on k+1, the video channel shows k): the machine delivers a frame
// every `frame_ms` = the slowest stage, and a frame reaches the screen `transport_ms` = the sum
// after its input was sampled.
//
//   A  scene manager (seed 000)  the counted model (studies/operation_counts.hpp) of the channel's
//                                objects, at 100 MHz and one cycle per operation (cig manager's
//                                defaults); Npl = the visible objects' mean subobjects, Np = 4 (A:)
//   B  geometric processor       the two-processor model (timing/geometry_timing.hpp); with the
//                                segment engine the edge generator runs beside it (seed 001: edges
//                                are formed at the vertex input rate), so B is the slower of the two
//   raster                       segment (D): both fields' passes of the cycle model; quadtree (E)
//                                and invparam (F): their cycle models' hardware_ms
//   video                        D: the video channel reading the segments (200 ns each); E, F: the
//                                frame buffer read out one pixel per 100 MHz clock (A:)
// Channels run on machines of their own: a frame's time is its slowest channel's.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace cig {

struct MachineTimingParams {
  double manager_clock_mhz = 100;  // seed 000: 100 MHz
  unsigned object_points = 4;      // A: Np, the points of an object's bounding planes
  double video_pixel_ns = 10;      // A: E and F read their frame buffer at one pixel per 100 MHz clock
  double budget_ms = 40;           // seed 001: a frame is two 20 ms TV fields (25 Hz)
};

struct StageTimes {
  double a_ms = 0, b_ms = 0, raster_ms = 0, video_ms = 0;
};

struct ChannelTiming {
  int channel = 0;
  StageTimes stages;
  double geometry_ms = 0, edge_generator_ms = 0;  // B's two parts (edges: segment engine only)
  double frame_ms = 0, transport_ms = 0;
  std::string limiting;          // "A", "B", "raster" or "video"
  long long underrun_lines = 0;  // segment engine: video lines not ready in time
};

struct FrameTiming {
  int frame = 0;
  std::vector<ChannelTiming> channels;
  double frame_ms = 0, transport_ms = 0;  // the slowest channel's
  std::string limiting;                   // its limiting stage
  long long underrun_lines = 0;
  bool over_budget = false;  // frame_ms > budget, or a video underrun
};

// One channel's stages from its report (ImageGenerator::render's ChannelOutput::report) for a
// raster of `raster` lines.
ChannelTiming time_channel(const nlohmann::ordered_json& channel_report, int raster, const MachineTimingParams& p);
FrameTiming time_frame(int frame, const std::vector<ChannelTiming>& channels, const MachineTimingParams& p);

nlohmann::ordered_json frame_timing_json(const FrameTiming& t);

// p-th percentile (0..100) of values by nearest rank; 0 for none.
double percentile(std::vector<double> values, double p);

}  // namespace cig
