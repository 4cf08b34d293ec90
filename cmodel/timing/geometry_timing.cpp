#include "timing/geometry_timing.hpp"

namespace cig {

double processor_ns(const OperationCounts& ops, const OperationCycles& c, double clock_ns) {
  const double cycles = double(ops.R) * c.R + double(ops.C) * c.C + double(ops.O) * c.O + double(ops.L) * c.L +
                        double(ops.A) * c.A + double(ops.M) * c.M + double(ops.D) * c.D;
  return cycles * clock_ns;
}

GeometryTiming time_geometry(const OperationCounts& transform, const OperationCounts& clip, std::uint64_t vertices,
                             const GeometryTimingParams& p) {
  GeometryTiming t;
  t.transform_ns = processor_ns(transform, p.transform, p.clock_ns);
  t.clip_ns = processor_ns(clip, p.clip, p.clock_ns);
  // A pipeline: processor 1 transforms the next subobject while processor 2 clips this one, so over a
  // frame the slower one sets the time (filling and draining the pipeline neglected).
  const bool clip_limits = t.clip_ns > t.transform_ns;
  t.frame_ns = clip_limits ? t.clip_ns : t.transform_ns;
  t.limiting = clip_limits ? "clip" : "transform";
  t.vertices_per_second = t.frame_ns > 0 ? double(vertices) * 1e9 / t.frame_ns : 0;
  return t;
}

}  // namespace cig
