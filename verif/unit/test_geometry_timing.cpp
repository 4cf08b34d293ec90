// Stage B in time (cmodel/timing/geometry_timing): each processor's time is its counts times its
// cycles times the clock, the frame takes the slower processor's time, and time scales with the
// counts.
#include <gtest/gtest.h>

#include "timing/geometry_timing.hpp"

namespace cig {
namespace {

// Round cycles so that the sums can be done by hand.
GeometryTimingParams hand_params() {
  GeometryTimingParams p;
  p.clock_ns = 100;
  p.transform = {5, 2, 1, 1, 1, 3, 40};  // R, C, O, L, A, M, D
  p.clip = {5, 2, 1, 1, 1, 3, 4};
  return p;
}

TEST(GeometryTiming, EachProcessorIsItsCountsTimesItsCycles) {
  OperationCounts transform, clip;
  transform.M = 36;  // four vertices' B (p - eye): 9 M + 9 A + 6 L each
  transform.A = 36;
  transform.L = 24;
  clip.M = 8;  // four vertices projected: 2 M + 2 D + 4 C each
  clip.D = 8;
  clip.C = 16;
  const GeometryTiming t = time_geometry(transform, clip, 4, hand_params());
  // Processor 1: 36 x 3 + 36 x 1 + 24 x 1 = 168 cycles of 100 ns.
  EXPECT_DOUBLE_EQ(t.transform_ns, 16800);
  // Processor 2: 8 x 3 + 8 x 4 + 16 x 2 = 88 cycles.
  EXPECT_DOUBLE_EQ(t.clip_ns, 8800);
  EXPECT_DOUBLE_EQ(t.frame_ns, 16800);
  EXPECT_EQ(t.limiting, "transform");
  EXPECT_DOUBLE_EQ(t.vertices_per_second, 4 * 1e9 / 16800);
  // Every kind is weighted: R, O and the divider.
  OperationCounts one;
  one.R = 1;
  one.O = 1;
  one.D = 1;
  EXPECT_DOUBLE_EQ(processor_ns(one, hand_params().transform, 100), (5 + 1 + 40) * 100);
  EXPECT_DOUBLE_EQ(processor_ns(one, hand_params().clip, 100), (5 + 1 + 4) * 100);
}

TEST(GeometryTiming, TheSlowerProcessorIsTheFrameTime) {
  OperationCounts transform, clip;
  transform.A = 10;  // 10 cycles
  clip.D = 5;        // 20 cycles
  const GeometryTiming t = time_geometry(transform, clip, 10, hand_params());
  EXPECT_DOUBLE_EQ(t.transform_ns, 1000);
  EXPECT_DOUBLE_EQ(t.clip_ns, 2000);
  EXPECT_DOUBLE_EQ(t.frame_ns, 2000);
  EXPECT_EQ(t.limiting, "clip");
  EXPECT_DOUBLE_EQ(t.vertices_per_second, 10 / 2e-6);
  // Nothing counted: no time, no rate.
  const GeometryTiming none = time_geometry({}, {}, 0);
  EXPECT_EQ(none.frame_ns, 0);
  EXPECT_EQ(none.vertices_per_second, 0);
}

TEST(GeometryTiming, DoublingTheCountsDoublesTheTime) {
  OperationCounts transform, clip;
  transform = {3, 7, 2, 50, 40, 45, 0};  // R, C, O, L, A, M, D
  clip = {0, 30, 8, 60, 70, 80, 12};
  const GeometryTiming once = time_geometry(transform, clip, 100);  // the default (assumed) figures
  OperationCounts transform2 = transform, clip2 = clip;
  transform2 += transform;
  clip2 += clip;
  const GeometryTiming twice = time_geometry(transform2, clip2, 100);
  EXPECT_DOUBLE_EQ(twice.transform_ns, 2 * once.transform_ns);
  EXPECT_DOUBLE_EQ(twice.clip_ns, 2 * once.clip_ns);
  EXPECT_DOUBLE_EQ(twice.frame_ns, 2 * once.frame_ns);
  EXPECT_EQ(twice.limiting, once.limiting);
  EXPECT_DOUBLE_EQ(twice.vertices_per_second, once.vertices_per_second / 2);
}

TEST(GeometryTiming, DefaultClockKeepsTheEdgeGeneratorsRate) {
  // Seed 001: edges are formed at the vertex input rate, at most 10 us per edge. Processor 2's
  // work for an unclipped quadrilateral (test_geometry_counts.cpp's hand count: outcodes
  // 4 x (15 M + 15 A + 5 C + 4 L), trivial tests 4 x (1 L + 2 O) + 2 C, clip buffer 16 L,
  // projection 4 x (2 M + 2 D + 4 C + 4 L), area 4 x (2 M + 2 A) + 1 C) is 76 M + 68 A + 39 C +
  // 52 L + 8 O + 8 D = 314 cycles at C = 2 and D = 4: it must take at most the 4 edges' 40 us and,
  // the clock being the slowest that does, not less than 314 cycles of the next slower 5 ns step.
  const GeometryTimingParams p;
  OperationCounts quad;
  quad.M = 76, quad.A = 68, quad.C = 39, quad.L = 52, quad.O = 8, quad.D = 8;
  const double ns = processor_ns(quad, p.clip, p.clock_ns);
  EXPECT_LE(ns, 4 * 10000.0);
  EXPECT_GT(processor_ns(quad, p.clip, p.clock_ns + 5), 4 * 10000.0);
  EXPECT_EQ(p.clip.D, 4);        // the added divider
  EXPECT_EQ(p.transform.D, 30);  // no divider on processor 1
}

}  // namespace
}  // namespace cig
