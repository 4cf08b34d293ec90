// Stage B in time: seed 001's geometric processor as two "Электроника МТ-70М" processors in a
// pipeline, fed by the operation counts stage B makes as it runs (GeometryStats::transform_ops and
// clip_ops, geometry/geometric_processor.hpp). Processor 1 does the matrix transformations,
// processor 2 the clipping and the perspective division, helped by the added floating-point
// divider; real numbers pass between them over the dedicated channel. Each processor's time is its
// counts times its cycles per operation kind times the clock; as a pipeline the frame takes the
// slower one's time (the channel is assumed to keep up: no stall is modelled).
//
// The seed gives no instruction times for the МТ-70М, and none was found in the reference corpus
// (searched: "Электроника МТ-70", "MT-70 array processor"): the cycles per kind below are
// ASSUMPTIONS (A:). The clock is derived from the seed: edges are formed "at the rate vertices
// reach the PGS, at most 10 us per edge", so the pair must hand over an unclipped quadrilateral's
// 4 vertices in 40 us. Processor 2 (the slower) spends 314 cycles on one (76 M + 68 A + 39 C +
// 52 L + 8 O + 8 D, verif/unit/test_geometry_counts.cpp's hand count): 40 us / 314 = 127 ns, and
// the clock is the slowest 5 ns step that fits, 125 ns (8 MHz; test_geometry_timing.cpp checks it).
#pragma once

#include <cstdint>
#include <string>

#include "common/operation_units.hpp"

namespace cig {

// Cycles per operation of seed 000's kinds on one processor.
struct OperationCycles {
  double R = 2;  // A: a word exchanged with the host (channel handshake + transfer)
  double C = 2;  // A: a comparison and the conditional jump, one instruction each
  double O = 1;  // A: a logical instruction
  double L = 1;  // A: a memory read or write
  double A = 1;  // A: a floating-point addition, one instruction
  double M = 1;  // A: a floating-point multiplication, one instruction
  double D = 4;  // A: on the added divider: operands out, its latency, the result back
};

struct GeometryTimingParams {
  double clock_ns = 125;  // derived above from seed 001's 10 us per edge
  // Processor 1, matrix transformations; it has no divider: a division is a software reciprocal
  // (A: 30 instructions, a table seed and Newton iterations of 2 M + 1 A), and it does none in
  // stage B as counted.
  OperationCycles transform{2, 2, 1, 1, 1, 1, 30};
  // Processor 2, clipping and the perspective division, with the added divider (seed 001).
  OperationCycles clip{};
};

struct GeometryTiming {
  double transform_ns = 0, clip_ns = 0;
  double frame_ns = 0;             // the slower processor: they work as a pipeline
  std::string limiting;            // "transform" (processor 1) or "clip" (processor 2)
  double vertices_per_second = 0;  // the given vertices over frame_ns
};

// One processor's time for `ops`: sum of count x cycles, times the clock.
double processor_ns(const OperationCounts& ops, const OperationCycles& cycles, double clock_ns);

// Stage B's time for one frame's counts; `vertices` is what vertices_per_second counts (e.g.
// GeometryStats::vertices_transformed).
GeometryTiming time_geometry(const OperationCounts& transform, const OperationCounts& clip, std::uint64_t vertices,
                             const GeometryTimingParams& p = {});

}  // namespace cig
