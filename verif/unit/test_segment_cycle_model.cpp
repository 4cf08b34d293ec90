// Stage D in time (cmodel/timing/segment_cycle_model): every expected figure below is worked out by
// hand in the comments from the rules in segment_cycle_model.hpp (seed 001's segment processor:
// 100 ns clock, 4 clocks per segment for eq. 3-4, 400 ns per segment write, 200 ns per read).
#include "timing/segment_cycle_model.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <random>
#include <stdexcept>
#include <vector>

namespace cig {
namespace {

SegmentLoadItem polygon(std::uint32_t edges, std::uint32_t even, std::uint32_t odd) {
  SegmentLoadItem item;
  item.edges = edges;
  item.segments[0] = even;
  item.segments[1] = odd;
  return item;
}

SegmentLoadItem light(std::uint32_t even, std::uint32_t odd) {
  SegmentLoadItem item = polygon(0, even, odd);
  item.light = true;
  return item;
}

SegmentLoadItem dropped(std::uint32_t edges, std::uint32_t even, std::uint32_t odd) {
  SegmentLoadItem item = polygon(edges, even, odd);
  item.dropped = true;
  return item;
}

SegmentLoad load_of(std::vector<SegmentLoadItem> items, int raster_lines = 0) {
  SegmentLoad load;
  load.raster_lines = raster_lines;
  load.items = std::move(items);
  load.line_segments.assign(raster_lines, 0);
  load.line_last_item.assign(raster_lines, -1);
  return load;
}

void expect_unit(const UnitTime& u, double busy, double stalled, double starved) {
  EXPECT_DOUBLE_EQ(u.busy_ns, busy);
  EXPECT_DOUBLE_EQ(u.stalled_ns, stalled);
  EXPECT_DOUBLE_EQ(u.starved_ns, starved);
}

// Short fields for the video tests: line_ns = (100000 - 20000) / (16 / 2) = 10000 ns, so a line
// period holds 50 reads of 200 ns; line k of a field is shown from 120000 + 10000 k.
SegmentTimingParams short_fields() {
  SegmentTimingParams p;
  p.field_ns = 100000;
  p.blanking_ns = 20000;
  return p;
}

TEST(SegmentCycleModel, LinePeriodSharesTheActiveField) {
  SegmentTimingParams p;
  // (20e6 - 1.6e6) / 256 = 71875 ns at n = 512; (18.4e6) / 8 = 2.3e6 at n = 16.
  EXPECT_DOUBLE_EQ(p.line_ns(512), 71875);
  EXPECT_DOUBLE_EQ(p.line_ns(16), 2.3e6);
}

TEST(SegmentCycleModel, OnePolygonPassIsHandComputed) {
  // 4 edges: 1 + 4 = 5 words = 500 ns read. Even field, 3 segments: generator 500-900, 900-1300,
  // 1300-1700; sorter 900-1300, 1300-1700, 1700-2100: pass 2100. Odd field, 2 segments: 1700.
  SegmentLoad load = load_of({polygon(4, 3, 2)});
  load.edges_formed = 4;
  const SegmentFrameTiming t = time_segment_frame({load});
  EXPECT_DOUBLE_EQ(t.field[0].pass_ns, 2100);
  EXPECT_DOUBLE_EQ(t.field[1].pass_ns, 1700);
  EXPECT_DOUBLE_EQ(t.back_ns, 3800);
  EXPECT_DOUBLE_EQ(t.front_ns, 40000);  // 4 edges x 10 us
  EXPECT_EQ(t.field[0].segments, 3u);
  EXPECT_EQ(t.field[1].segments, 2u);
  expect_unit(t.field[0].preprocessor, 500, 0, 1600);
  expect_unit(t.field[0].generator, 1200, 0, 900);  // waits 500 for the record, 400 for the last write
  expect_unit(t.field[0].sorter, 1200, 0, 900);
  expect_unit(t.field[1].generator, 800, 0, 900);
  EXPECT_TRUE(t.fits_fields);
  // Generator and sorter are both busy 1200: the tie goes to the first in pipeline order.
  EXPECT_EQ(t.limiting_unit, "segment generator");
}

TEST(SegmentCycleModel, SorterBoundPassAndGeneratorStall) {
  SegmentTimingParams p;
  p.write_ns = 1000;
  p.segment_queue = 4;
  // 2 edges: 300 ns read; segment j (1..40) computed at 300 + 400 j unless stalled; the sorter,
  // slower, takes segment j at 700 + 1000 (j - 1): pass = 700 + 40 x 1000 = 40700.
  const SegmentFrameTiming t = time_segment_frame({load_of({polygon(2, 40, 0)})}, p);
  EXPECT_DOUBLE_EQ(t.field[0].pass_ns, 40700);
  // Segment j enters the queue once the sorter took j - 4 (at 1000 j - 4300): first later than its
  // computation (300 + 400 j) at j = 8: 3700 - 3500 = 200; from then on each waits 1000 - 400 = 600.
  // Stalled 200 + 32 x 600 = 19400; busy 40 x 400; starved 40700 - 16000 - 19400 = 5300.
  expect_unit(t.field[0].generator, 16000, 19400, 5300);
  expect_unit(t.field[0].sorter, 40000, 0, 700);
  expect_unit(t.field[0].preprocessor, 300, 0, 40400);
  // Odd field: no segments, the pass is the preprocessor's read.
  EXPECT_DOUBLE_EQ(t.field[1].pass_ns, 300);
  EXPECT_EQ(t.limiting_unit, "Y sorter");
}

TEST(SegmentCycleModel, PreprocessorBoundPass) {
  // 10 polygons of 19 edges: 20 words = 2000 ns each, one segment per field. Record i read by
  // 2000 (i + 1), its segment computed 400 later and written 400 after that: pass 20000 + 800.
  const SegmentFrameTiming t = time_segment_frame({load_of(std::vector<SegmentLoadItem>(10, polygon(19, 1, 1)))});
  for (int f = 0; f < 2; ++f) {
    EXPECT_DOUBLE_EQ(t.field[f].pass_ns, 20800);
    expect_unit(t.field[f].preprocessor, 20000, 0, 800);
    expect_unit(t.field[f].generator, 4000, 0, 16800);
    expect_unit(t.field[f].sorter, 4000, 0, 16800);
  }
  EXPECT_EQ(t.limiting_unit, "preprocessor");
}

TEST(SegmentCycleModel, PreprocessorHoldsARecordWhileTheRecordQueueIsFull) {
  SegmentTimingParams p;
  p.preprocessor_queue = 1;
  // Record 0: 1 edge (200 ns read), 10 segments; records 1-3: header only (100 ns), 1 segment.
  // Generator: record 0 taken at 200, done 4200; record 1 at 4200, done 4600; 2 at 4600; 3 at 5000.
  // Preprocessor: r1 read 200-300, queued at once (r0 taken at 200); r2 read 300-400, held until
  // r1 is taken (4200): 3800; r3 read 4200-4300, held until r2 is taken (4600): 300.
  // Segments are computed every 400 from 600 and written 400 later: the 13th is written at 5800.
  const SegmentLoad load = load_of({polygon(1, 10, 0), polygon(0, 1, 0), polygon(0, 1, 0), polygon(0, 1, 0)});
  const SegmentFrameTiming t = time_segment_frame({load}, p);
  EXPECT_DOUBLE_EQ(t.field[0].pass_ns, 5800);
  expect_unit(t.field[0].preprocessor, 500, 4100, 1200);
  expect_unit(t.field[0].generator, 5200, 0, 600);
  expect_unit(t.field[0].sorter, 5200, 0, 600);
}

TEST(SegmentCycleModel, DroppedRecordCostsItsHeaderAndALightItsOwnCosts) {
  // A dropped polygon (10 edges, its segments ignored): 1 word = 100 ns, no generator time.
  // A light: 2 words (100-300), 3 segments of 1 clock: computed 400, 500, 600; written 400-800,
  // 800-1200, 1200-1600. The light's line is ready at 1600.
  SegmentLoad load = load_of({dropped(10, 5, 5), light(3, 0)});
  load.edges_formed = 10;
  const SegmentFrameTiming t = time_segment_frame({load});
  EXPECT_DOUBLE_EQ(t.front_ns, 100000);  // a dropped polygon's edges were still formed
  EXPECT_DOUBLE_EQ(t.field[0].pass_ns, 1600);
  EXPECT_EQ(t.field[0].segments, 3u);
  expect_unit(t.field[0].preprocessor, 300, 0, 1300);
  expect_unit(t.field[0].generator, 300, 0, 1300);
  expect_unit(t.field[0].sorter, 1200, 0, 400);
  EXPECT_DOUBLE_EQ(t.field[1].pass_ns, 300);
  EXPECT_EQ(t.field[1].segments, 0u);
}

TEST(SegmentCycleModel, VideoLineWithTooManySegmentsUnderruns) {
  const SegmentTimingParams p = short_fields();
  // One polygon, 2 edges, 130 even segments: written by 300 + 130 x 400 + 400 = 52700.
  // Raster line 2 (k = 1): 10 segments; line 4 (k = 2): 70; line 10 (k = 5): 50 (exactly a period).
  SegmentLoad load = load_of({polygon(2, 130, 0)}, 16);
  for (auto [line, segments] : {std::pair{2, 10u}, {4, 70u}, {10, 50u}}) {
    load.line_segments[line] = segments;
    load.line_last_item[line] = 0;
  }
  const SegmentFrameTiming t = time_segment_frame({load}, p);
  const FieldTiming& even = t.field[0];
  EXPECT_DOUBLE_EQ(even.pass_ns, 52700);
  // k = 2: its buffer frees when line 0 has been shown (display_1 = 130000); 70 x 200 = 14000 ends
  // at 144000, 4000 after display_2 = 140000: 4000 / 200 = 20 segments not shown.
  // k = 5: starts at display_4 = 160000, ends at 170000 = display_5: no underrun, slack 0.
  EXPECT_EQ(even.underrun_lines, 1u);
  EXPECT_EQ(even.segments_not_shown, 20u);
  EXPECT_EQ(even.read_bound_underruns, 1u);
  EXPECT_DOUBLE_EQ(even.worst_line_slack_ns, -4000);
  EXPECT_DOUBLE_EQ(even.video_busy_ns, (10 + 50 + 50) * 200.0);
  // Odd field, no segments: from k = 2 on, each line's read starts at the display before: slack 10000.
  EXPECT_EQ(t.field[1].underrun_lines, 0u);
  EXPECT_DOUBLE_EQ(t.field[1].worst_line_slack_ns, 10000);
  EXPECT_EQ(t.underrun_lines, 1u);
  EXPECT_FALSE(t.fits_fields);
  EXPECT_EQ(t.limiting_unit, "video channel");
  // Slower reads, 210 ns: line 4 ends at 130000 + 14700, 4700 late: 4700 / 210 = 22.4 -> 23 lost;
  // line 10 from 160000 + 10500 is 500 late: 2.4 -> 3 lost (a part-read segment is not shown).
  SegmentTimingParams slower = p;
  slower.read_ns = 210;
  const FieldTiming slow = time_segment_frame({load}, slower).field[0];
  EXPECT_EQ(slow.underrun_lines, 2u);
  EXPECT_EQ(slow.segments_not_shown, 26u);
  EXPECT_DOUBLE_EQ(slow.worst_line_slack_ns, -4700);
}

TEST(SegmentCycleModel, VideoLineReadyLateUnderruns) {
  const SegmentTimingParams p = short_fields();
  // Item 0: 2 edges, 299 segments, computed every 400 from 700, last written at 120300.
  // Item 1: header only, read by 400, taken at 119900, computed 120300, written 120700.
  // Line 0 (k = 0) is item 1's: shown from 120000, ready at 120700 -> underrun, its 1 segment lost,
  // slack 120000 - (120700 + 200) = -900. Item 0's lines k = 2..6 take 50 segments each, starting at
  // display_{k-1} and ending exactly at display_k; k = 7 takes 49: slack 200.
  SegmentLoad load = load_of({polygon(2, 299, 0), polygon(0, 1, 0)}, 16);
  load.line_segments[0] = 1;
  load.line_last_item[0] = 1;
  for (int line = 4; line <= 14; line += 2) {
    load.line_segments[line] = line == 14 ? 49 : 50;
    load.line_last_item[line] = 0;
  }
  const SegmentFrameTiming t = time_segment_frame({load}, p);
  EXPECT_DOUBLE_EQ(t.field[0].pass_ns, 120700);
  EXPECT_EQ(t.field[0].underrun_lines, 1u);
  EXPECT_EQ(t.field[0].segments_not_shown, 1u);
  EXPECT_EQ(t.field[0].read_bound_underruns, 0u);  // 200 ns of reading fits easily: it was late
  EXPECT_DOUBLE_EQ(t.field[0].worst_line_slack_ns, -900);
  EXPECT_DOUBLE_EQ(t.field[0].video_busy_ns, 299 * 200.0);
  // Not the video channel: generator and sorter both busy 120000, the tie to the generator.
  EXPECT_EQ(t.limiting_unit, "segment generator");
  EXPECT_FALSE(t.fits_fields);
}

TEST(SegmentCycleModel, TwoPartsRunInParallelAndShareTheVideoChannel) {
  const SegmentTimingParams p = short_fields();
  // Part A: one polygon, 2 edges, 60 even segments (30 on line 0, 30 on line 4): written by
  // 300 + 60 x 400 + 400 = 24700. Part B: first a 99-edge polygon with no segments (read 0-10000),
  // then the same polygon (read by 10300): 10300 + 24000 + 400 = 34700.
  SegmentLoad a = load_of({polygon(2, 60, 0)}, 16);
  SegmentLoad b = load_of({polygon(99, 0, 0), polygon(2, 60, 0)}, 16);
  a.edges_formed = 10;
  b.edges_formed = 30;
  for (int line : {0, 4}) {
    a.line_segments[line] = b.line_segments[line] = 30;
    a.line_last_item[line] = 0;
    b.line_last_item[line] = 1;
  }
  const SegmentFrameTiming t = time_segment_frame({a, b}, p);
  EXPECT_DOUBLE_EQ(t.front_ns, 300000);  // max(10, 30) edges x 10 us
  EXPECT_DOUBLE_EQ(t.field[0].pass_ns, 34700);
  EXPECT_DOUBLE_EQ(t.field[1].pass_ns, 10300);  // B's reads; A's are 300
  EXPECT_DOUBLE_EQ(t.back_ns, 45000);
  EXPECT_EQ(t.field[0].segments, 120u);
  expect_unit(t.field[0].preprocessor, 10300, 0, 24400);  // part B's (the longer pass)
  // Line 0: ready when both parts have written it (34700), 60 x 200 read: slack 120000 - 46700.
  // Line 4 (k = 2): starts at display_1 = 130000, 12000 of reads end 2000 after display_2:
  // 10 segments lost, though 30 x 200 from either part alone would fit.
  EXPECT_EQ(t.field[0].underrun_lines, 1u);
  EXPECT_EQ(t.field[0].segments_not_shown, 10u);
  EXPECT_DOUBLE_EQ(t.field[0].worst_line_slack_ns, -2000);
  EXPECT_DOUBLE_EQ(t.field[0].video_busy_ns, (60 + 50) * 200.0);
  EXPECT_EQ(t.limiting_unit, "video channel");
  EXPECT_EQ(time_segment_frame({a}, p).underrun_lines, 0u);
  EXPECT_EQ(time_segment_frame({b}, p).underrun_lines, 0u);
  // Line 0's slack alone: with 8 buffers (a whole field) no line waits for a buffer, so an empty line
  // k >= 1 is read at once after line 0 (46700) and its slack exceeds line 0's 120000 - 46700.
  SegmentTimingParams buffered = p;
  buffered.line_buffers = 8;
  a.line_segments[4] = b.line_segments[4] = 0;
  EXPECT_DOUBLE_EQ(time_segment_frame({a, b}, buffered).field[0].worst_line_slack_ns, 120000 - 46700);
  // Ready when only part A had written it (24700): the slack would be 10000 more.
  b.line_last_item[0] = -1;
  EXPECT_DOUBLE_EQ(time_segment_frame({a, b}, buffered).field[0].worst_line_slack_ns, 120000 - 36700);
}

// A random but consistent load: each written segment on a random line of its field.
SegmentLoad random_load(std::mt19937& rng, int raster_lines) {
  std::uniform_int_distribution<int> count(0, 40), kind(0, 9), edges(0, 30), segments(0, 12),
      line(0, raster_lines / 2 - 1);
  SegmentLoad load = load_of({}, raster_lines);
  const int items = count(rng);
  for (int i = 0; i < items; ++i) {
    const int k = kind(rng);
    SegmentLoadItem item = polygon(k == 0 ? 0 : edges(rng), segments(rng), segments(rng));
    item.light = k == 0;
    item.dropped = k == 1;
    for (int f = 0; f < 2 && !item.dropped; ++f)
      for (std::uint32_t s = 0; s < item.segments[f]; ++s) {
        const int l = 2 * line(rng) + f;
        load.line_segments[l] += 1;
        load.line_last_item[l] = i;
      }
    load.edges_formed += item.edges;
    load.items.push_back(item);
  }
  return load;
}

SegmentTimingParams random_params(std::mt19937& rng) {
  std::uniform_int_distribution<int> queue(0, 6), clocks(1, 6), write(1, 6);
  SegmentTimingParams p;
  p.preprocessor_queue = queue(rng);
  p.segment_queue = queue(rng) * 3;
  p.iz_clocks_per_segment = clocks(rng);
  p.write_ns = 100.0 * write(rng);
  return p;
}

TEST(SegmentCycleModel, UnitTimesAddUpToThePass) {
  std::mt19937 rng(1);
  for (int c = 0; c < 300; ++c) {
    const SegmentTimingParams p = random_params(rng);
    const SegmentFrameTiming t = time_segment_frame({random_load(rng, 16), random_load(rng, 16)}, p);
    for (const FieldTiming& ft : t.field)
      for (const UnitTime* u : {&ft.preprocessor, &ft.generator, &ft.sorter}) {
        EXPECT_NEAR(u->busy_ns + u->stalled_ns + u->starved_ns, ft.pass_ns, 1e-6);
        EXPECT_GE(u->stalled_ns, 0);
        EXPECT_GE(u->starved_ns, -1e-6);
      }
    EXPECT_DOUBLE_EQ(t.field[0].sorter.stalled_ns, 0);  // the sorter has no output queue
  }
}

TEST(SegmentCycleModel, AddingSegmentsNeverShortensAPass) {
  std::mt19937 rng(7);
  for (int c = 0; c < 300; ++c) {
    const SegmentTimingParams p = random_params(rng);
    SegmentLoad load = random_load(rng, 16);
    if (load.items.empty()) continue;
    const SegmentFrameTiming before = time_segment_frame({load}, p);
    std::uniform_int_distribution<std::size_t> pick(0, load.items.size() - 1);
    std::uniform_int_distribution<int> field(0, 1), more(1, 20);
    load.items[pick(rng)].segments[field(rng)] += more(rng);
    const SegmentFrameTiming after = time_segment_frame({load}, p);
    for (int f = 0; f < 2; ++f) EXPECT_GE(after.field[f].pass_ns, before.field[f].pass_ns) << "case " << c;
  }
}

TEST(SegmentCycleModel, FrameOfAHundredThousandSegmentsPerField) {
  // 1000 polygons of 2 edges, 100 segments per field each, at the seed's rates: generator and
  // sorter both 400 per segment, so the pass is the first read (300) + 100000 x 400 + the last write.
  const int n = 512;
  SegmentLoad load = load_of(std::vector<SegmentLoadItem>(1000, polygon(2, 100, 100)), n);
  for (int i = 0; i < 1000; ++i)
    for (int f = 0; f < 2; ++f) {
      load.line_segments[2 * (i % 256) + f] += 100;
      load.line_last_item[2 * (i % 256) + f] = i;
    }
  const auto start = std::chrono::steady_clock::now();
  const SegmentFrameTiming t = time_segment_frame({load});
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  RecordProperty("ms", std::to_string(ms));
  EXPECT_LT(ms, 500);  // linear work; a quadratic model would take minutes
  for (int f = 0; f < 2; ++f) {
    EXPECT_EQ(t.field[f].segments, 100000u);
    EXPECT_DOUBLE_EQ(t.field[f].pass_ns, 300 + 100000 * 400.0 + 400);
  }
  EXPECT_FALSE(t.fits_fields);  // 40 ms of writes per 20 ms field
}

TEST(SegmentCycleModel, InvalidInputThrows) {
  const SegmentLoad good = load_of({polygon(2, 1, 1)}, 4);
  EXPECT_NO_THROW(time_segment_frame({good}));
  SegmentLoad other_raster = load_of({polygon(2, 1, 1)}, 6);
  EXPECT_THROW(time_segment_frame({good, other_raster}), std::invalid_argument);
  SegmentLoad short_segments = good;
  short_segments.line_segments.pop_back();
  EXPECT_THROW(time_segment_frame({short_segments}), std::invalid_argument);
  SegmentLoad long_items = good;
  long_items.line_last_item.push_back(-1);
  EXPECT_THROW(time_segment_frame({long_items}), std::invalid_argument);
  SegmentLoad no_such_item = good;
  no_such_item.line_last_item[1] = 1;
  EXPECT_THROW(time_segment_frame({no_such_item}), std::invalid_argument);
  SegmentTimingParams no_buffer;
  no_buffer.line_buffers = 0;
  EXPECT_THROW(time_segment_frame({good}, no_buffer), std::invalid_argument);
  SegmentTimingParams negative_queue;
  negative_queue.segment_queue = -1;
  EXPECT_THROW(time_segment_frame({good}, negative_queue), std::invalid_argument);
}

TEST(SegmentCycleModel, NoPartsGiveZeros) {
  const SegmentFrameTiming t = time_segment_frame({});
  EXPECT_DOUBLE_EQ(t.front_ns, 0);
  EXPECT_DOUBLE_EQ(t.back_ns, 0);
  EXPECT_DOUBLE_EQ(t.field[0].pass_ns, 0);
  EXPECT_EQ(t.underrun_lines, 0u);
  EXPECT_FALSE(t.fits_fields);
  EXPECT_EQ(t.limiting_unit, "");
}

}  // namespace
}  // namespace cig
