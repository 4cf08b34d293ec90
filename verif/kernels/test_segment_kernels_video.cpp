// The segment processor's video half (SPEC D, seed 001): the Y sorter and segment memory
// (hls/segment/y_sorter.hpp), light points through the sorter and the video channel
// (light_segments.hpp, video_channel.hpp), the video channel itself (priority, screen door,
// colour x I, fog table, box filter, majority id) by hand-built cases with exact expectations and
// against its double twin with a per-sample bound derived from the formats. The golden vectors
// of the whole chain are in test_segment_kernels_golden.cpp, the front half and the digest test in
// test_segment_kernels.cpp.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "digest.hpp"
#include "hls/segment/edge_generator.hpp"
#include "hls/segment/light_segments.hpp"
#include "hls/segment/segment_generator.hpp"
#include "hls/segment/video_channel.hpp"
#include "hls/segment/y_sorter.hpp"
#include "segment_test_support.hpp"
#include "test_segment_kernels.hpp"

namespace cig::hls {
namespace {

using namespace segtest;
using namespace segkernels;
using kernel_test::Digest;
using P = DefaultSegmentArith;
using X = P::X;
using Intensity = P::Intensity;
constexpr int kFx = X::frac_bits, kFi = Intensity::frac_bits;

#ifdef CIG_HLS_SYSTEMC
constexpr int kScale = 2;  // random-sample counts (the SystemC types are slower)
#else
constexpr int kScale = 4;
#endif

// X of a position given in half units (exact in every X format: one fractional bit is enough).
X x_half(i128 h) { return X::from_raw_value(std::int64_t(h * (i128(1) << (kFx - 1)))); }

// ---- Y sorter ------------------------------------------------------------------------------------

Segment<P> random_segment(Rng& rng, int lines, int serial) {
  Segment<P> s;
  s.line = UInt<10>(std::uint64_t(below(rng, lines)));
  s.type = UInt<3>(std::uint64_t(between(rng, 1, 4)));
  const int rf = int(below(rng, 4)), rl = int(between(rng, rf, 3));
  s.row_first = UInt<2>(std::uint64_t(rf));
  s.row_last = UInt<2>(std::uint64_t(rl));
  for (int r = 0; r < kRowsPerLine; ++r) {
    s.xl[r] = X::from_raw_value(between(rng, -(std::int64_t(8) << kFx), std::int64_t(4100) << kFx));
    s.xr[r] = X::from_raw_value(between(rng, -(std::int64_t(8) << kFx), std::int64_t(4100) << kFx));
  }
  s.il = Intensity::from_raw_value(std::uint64_t(below(rng, std::int64_t(1) << Intensity::width)));
  s.ir = Intensity::from_raw_value(std::uint64_t(below(rng, std::int64_t(1) << Intensity::width)));
  s.zl = zcode(int(below(rng, 0x8000)));
  s.zr = zcode(int(below(rng, 0x8000)));
  s.source = UInt<16>(std::uint64_t(serial & 0xFFFF));
  s.is_light = below(rng, 8) == 0;
  s.opaque = below(rng, 4) != 0;
  s.channel = UInt<3>(std::uint64_t(below(rng, 8)));
  return s;
}

// Per-line lists in arrival (= priority) order, heads and tails, counts per line, even lines in
// bank 0 and odd lines in bank 1, a full bank drops (and counts) its segments while the other goes
// on, every field (channel number included) stored as it came. K words per bank: small, so that
// the banks overflow.
template <int K>
void work_y_sorter(int scale, Digest* dg) {
  auto mem = std::make_unique<SegmentMemory<P, K>>();
  SegmentMemory<P, K>& m = *mem;
  Rng rng(0x5027 + K);
  for (int round = 0; round < 6 * scale; ++round) {
    const int lines = 1 << (kMinRasterLog2 + round % 3);
    y_sorter_reset(m, lines);
    ASSERT_EQ(m.used[0], 0);
    ASSERT_EQ(m.used[1], 0);
    ASSERT_EQ(m.dropped[0].value(), 0u);
    ASSERT_EQ(m.dropped[1].value(), 0u);
    for (int l = 0; l < lines; ++l) {
      ASSERT_EQ(m.head[l], kNullPointer);
      ASSERT_EQ(int(m.count[l].value()), 0);
    }
    std::vector<std::vector<std::vector<std::int64_t>>> expect(static_cast<std::size_t>(lines));
    int stored[2] = {0, 0}, dropped[2] = {0, 0};
    // Beyond the capacity of both banks, or within it.
    const int pushes = round % 2 == 0 ? 3 * K : int(below(rng, K));
    for (int t = 0; t < pushes; ++t) {
      const Segment<P> s = random_segment(rng, lines, t);
      const int b = int(s.line.value()) & 1;
      const bool fits = stored[b] < K;
      ASSERT_EQ(y_sort(s, m), fits) << "segment " << t;
      if (fits) {
        ++stored[b];
        std::vector<std::int64_t> w;
        segment_words(s, w);
        expect[s.line.value()].push_back(w);
      } else {
        ++dropped[b];
      }
      ASSERT_EQ(m.used[b], stored[b]);
      ASSERT_EQ(int(m.dropped[b].value()), dropped[b]);
    }
    if (round % 2 == 0) {
      EXPECT_EQ(m.used[0], K);
      EXPECT_EQ(m.used[1], K);
      EXPECT_GT(dropped[0] + dropped[1], 0);
    }
    int walked[2] = {0, 0};
    for (int l = 0; l < lines; ++l) {
      const int b = l & 1;
      std::vector<std::vector<std::int64_t>> got;
      int last = kNullPointer;
      for (int p = m.head[l], hops = 0; p != kNullPointer; p = m.next[b][p], ++hops) {
        ASSERT_LT(hops, K) << "line " << l << ": the list does not end";
        ASSERT_TRUE(p >= 0 && p < m.used[b]);
        ASSERT_EQ(int(m.seg[b][p].line.value()), l);  // a line's list holds only its segments
        std::vector<std::int64_t> w;
        segment_words(m.seg[b][p], w);
        got.push_back(w);
        last = p;
      }
      ASSERT_EQ(got, expect[std::size_t(l)]) << "line " << l;  // arrival order, every field
      ASSERT_EQ(int(m.count[l].value()), int(got.size()));
      ASSERT_EQ(m.head[l] == kNullPointer, got.empty());
      if (!got.empty()) { ASSERT_EQ(m.tail[l], last); }
      walked[b] += int(got.size());
      if (dg) {
        dg->add(m.count[l].value());
        for (const auto& w : got) digest_words(dg, w);
      }
    }
    EXPECT_EQ(walked[0], stored[0]);  // every stored segment is on its line's list, once
    EXPECT_EQ(walked[1], stored[1]);
  }
}

TEST(YSorter, ListsCountsBanksAndOverflow) { work_y_sorter<24>(kScale, nullptr); }

// The real banks: 48K segments per field. Even lines fill bank 0 and then drop; odd lines still go
// into bank 1.
TEST(YSorter, FortyEightKSegmentBanks) {
  auto mem = std::make_unique<SegmentMemory<P>>();
  y_sorter_reset(*mem, 1024);
  Rng rng(48);
  Segment<P> s = random_segment(rng, 1, 0);
  for (int t = 0; t < kSegmentBankWords + 5; ++t) {
    s.line = UInt<10>(std::uint64_t(2 * (t % 512)));
    ASSERT_EQ(y_sorter_top(s, *mem), t < kSegmentBankWords);
  }
  s.line = UInt<10>(7);
  EXPECT_TRUE(y_sorter_top(s, *mem));
  EXPECT_EQ(mem->used[0], kSegmentBankWords);
  EXPECT_EQ(mem->used[1], 1);
  EXPECT_EQ(int(mem->dropped[0].value()), 5);
  EXPECT_EQ(int(mem->dropped[1].value()), 0);
  EXPECT_EQ(int(mem->count[0].value()), kSegmentBankWords / 512);
  EXPECT_EQ(int(mem->count[7].value()), 1);
}

// ---- Light points through the Y sorter and the video channel ------------------------------------------

// Lights (every diameter, centres anywhere including the screen border) in priority order, then a
// polygon covering the whole screen behind them. Each light segment is on the list of its own line
// (row / 4), in arrival order; after render_line every sample inside a light's disc (half units:
// (2 X_i - 2 X)^2 + (2 Y_k - 2 Y)^2 <= D^2, the reference's disc) is owned by the first such light,
// with its colour x I exactly (fog factor 0: c * I / 256, exact in the Sample format); every other
// sample by the polygon; the sample and pixel ids are the polygon's (lights aside).
void work_lights_through_video(int scale, Digest* dg) {
  Rng rng(0x1167);
  for (int log2 = kMinRasterLog2; log2 <= kMinRasterLog2 + 2; ++log2)
    for (int trial = 0; trial < scale; ++trial) {
      const Lattice lat(log2);
      const int n = lat.n, cols = lat.rows;
      VideoRig<P, 4096> rig;
      VideoTables<P>& t = *rig.tables;
      for (int code = 0; code < (1 << 15); ++code) t.fog.f[code] = P::FogFactor::from_raw_value(0);
      for (int c = 0; c < 3; ++c) t.fog_colour[c] = t.background[c] = UInt<8>(std::uint64_t(9 + c));
      y_sorter_reset(*rig.mem, n);
      struct Light {
        int x, y, d, i, id;
      };
      std::vector<Light> lights;
      std::vector<std::vector<std::pair<int, int>>> on_line(static_cast<std::size_t>(n));  // (id, row) per line
      const int count = int(between(rng, 3, 9));
      for (int k = 0; k < count; ++k) {
        const bool border = below(rng, 3) == 0;
        Light l{int(border ? (below(rng, 2) ? below(rng, 8) : 4095 - below(rng, 8)) : below(rng, 4096)),
                int(below(rng, 4096)), int(below(rng, 8)), int(below(rng, 256)), k};
        if (k < 2) {  // two lights on top of each other: the first one wins the shared samples
          l.x = 2000 + k, l.y = 2001, l.d = 7 - k;
        }
        lights.push_back(l);
        FormattedPrimitive f;
        f.is_light = true;
        f.n = UInt<5>(1);
        f.v[0] = {UInt<12>(std::uint64_t(l.x)), UInt<12>(std::uint64_t(l.y)), UInt<8>(std::uint64_t(l.i)),
                  zcode(127 * 128 + k)};
        f.d = UInt<3>(std::uint64_t(l.d));
        f.id = UInt<16>(std::uint64_t(k));
        for (int c = 0; c < 3; ++c) t.light_colour[k][c] = UInt<8>(std::uint64_t(40 * k + 50 * c + 1) & 255);
        Segment<P> out[kMaxLightSegments];
        const int segs = generate_light_segments<P>(f, log2, UInt<3>(2), out);
        for (int s = 0; s < segs; ++s) {
          ASSERT_TRUE(y_sort(out[s], *rig.mem));
          const int row = 4 * int(out[s].line.value()) + int(out[s].row_first.value());
          on_line[std::size_t(row / 4)].push_back({k, row});
        }
      }
      // The ground: the whole screen, priority after every light.
      IntPolygon ground;
      ground.n = 4;
      const int gx[] = {0, 4095, 4095, 0}, gy[] = {0, 0, 4095, 4095};
      for (int k = 0; k < 4; ++k) ground.x[k] = gx[k], ground.y[k] = gy[k], ground.i[k] = 200, ground.z[k] = 130 * 128;
      ground.id = 0;
      for (int c = 0; c < 3; ++c) t.polygon_colour[0][c] = UInt<8>(std::uint64_t(100 + c));
      PolygonEdges<P> e;
      generate_edges<P>(fixed_input(ground), log2, e);
      auto segs = std::make_unique<Segment<P>[]>(kMaxLines);
      Segment<P>(&out)[kMaxLines] = *reinterpret_cast<Segment<P>(*)[kMaxLines]>(segs.get());
      const int gsegs = generate_segments<P>(e, log2, UInt<3>(2), false, out);
      ASSERT_EQ(gsegs, n);
      for (int s = 0; s < gsegs; ++s) ASSERT_TRUE(y_sort(out[s], *rig.mem));
      for (int line = 0; line < n; ++line) {
        // The line's list: its lights' segments in arrival order, then the ground's.
        std::vector<std::pair<int, int>> got;
        const int b = line & 1;
        int p = rig.mem->head[line];
        for (; p != kNullPointer && rig.mem->seg[b][p].is_light; p = rig.mem->next[b][p]) {
          const Segment<P>& s = rig.mem->seg[b][p];
          ASSERT_EQ(int(s.line.value()), line);
          ASSERT_EQ(s.channel.value(), 2u);
          got.push_back({int(s.source.value()), 4 * line + int(s.row_first.value())});
        }
        ASSERT_EQ(got, on_line[std::size_t(line)]) << "line " << line;
        ASSERT_NE(p, kNullPointer);
        ASSERT_FALSE(rig.mem->seg[b][p].is_light);
        ASSERT_EQ(rig.mem->next[b][p], kNullPointer);
        const int read = render_line(line, log2, *rig.mem, t, *rig.line, *rig.pixels);
        ASSERT_EQ(read, int(rig.mem->count[line].value()));
        ASSERT_EQ(read, int(got.size()) + 1);
        for (int r = 0; r < kRowsPerLine; ++r)
          for (int i = 0; i < cols; ++i) {
            const i128 sx = lat.half(i), sy = lat.half(4 * line + r);
            int owner = -1;
            for (const Light& l : lights) {
              const i128 dx = sx - 2 * l.x, dy = sy - 2 * l.y;
              if (dx * dx + dy * dy <= i128(l.d) * l.d) {
                owner = l.id;
                break;
              }
            }
            ASSERT_TRUE(rig.line->owned[r][i]);
            ASSERT_EQ(rig.line->polygon[r][i], 0) << "row " << 4 * line + r << " col " << i;
            if (owner < 0) continue;
            const Light& l = lights[std::size_t(owner)];
            for (int c = 0; c < 3; ++c)
              ASSERT_EQ(raw_of(rig.line->rgb[r][i][c]), std::int64_t(t.light_colour[owner][c].value()) * l.i)
                  << "row " << 4 * line + r << " col " << i << " light " << owner;
            if (dg) dg->add(std::uint64_t(owner));
          }
        for (int px = 0; px < n; ++px) {
          ASSERT_EQ(rig.pixels->id[px], 0);
          if (dg)
            for (int c = 0; c < 3; ++c) dg->add(rig.pixels->rgb[px][c].value());
        }
      }
    }
}

TEST(LightSegments, ThroughYSorterAndVideoChannel) { work_lights_through_video(kScale, nullptr); }

// ---- Video channel: hand-built cases ---------------------------------------------------------------

// N = 16: 64 sample columns at X_i = 64 i + 31 grid units, pixel p = columns 4p .. 4p + 3.
constexpr int kLog2 = 4;

// A segment covering, on rows rf..rl of a line, exactly the columns [c0, c1): its left X is column
// c0's position (inclusive), its right X column c1's (exclusive). Constant I (a level) and Z.
Segment<P> columns(int line, int rf, int rl, int c0, int c1, int level, int z, int source, bool opaque = true,
                   bool light = false) {
  const Lattice lat(kLog2);
  Segment<P> s;
  s.line = UInt<10>(std::uint64_t(line));
  s.type = UInt<3>(kSegMiddle);
  s.row_first = UInt<2>(std::uint64_t(rf));
  s.row_last = UInt<2>(std::uint64_t(rl));
  for (int r = 0; r < kRowsPerLine; ++r) {
    s.xl[r] = x_half(lat.half(c0));
    s.xr[r] = x_half(lat.half(c1));
  }
  s.il = s.ir = Intensity(UInt<8>(std::uint64_t(level)));
  s.zl = s.zr = zcode(z);
  s.source = UInt<16>(std::uint64_t(source));
  s.opaque = opaque;
  s.is_light = light;
  return s;
}

// The exact sample value of colour c, level I (exact in Intensity), fog factor f / 256 and fog colour
// g, in 1/256 output LSB: c I / 256 (exact: raw c * I), then s (1 - f) + g f rounded half up.
std::int64_t exact_sample(int c, int level, int f, int g) {
  const i128 s = i128(c) * level;  // c * I / 256 in units of 1/256
  return std::int64_t(round_half_up(s * (256 - f) + i128(g) * 256 * f, 256));
}

TEST(VideoChannel, HandBuiltPriorityDoorFogFilterAndIds) {
  VideoRig<P, 256> rig;
  VideoTables<P>& t = *rig.tables;
  const int fog_code = 127 * 128 + 5, fog_f = 64;  // one depth code fogged by 1/4
  for (int code = 0; code < (1 << 15); ++code)
    t.fog.f[code] = P::FogFactor::from_raw_value(code == fog_code ? fog_f : 0);
  const int fog[3] = {16, 32, 48}, bg[3] = {7, 8, 9};
  for (int c = 0; c < 3; ++c) {
    t.fog_colour[c] = UInt<8>(std::uint64_t(fog[c]));
    t.background[c] = UInt<8>(std::uint64_t(bg[c]));
  }
  const int colour[11][3] = {{0, 0, 0}, {200, 100, 50}, {102, 30, 250}, {10, 20, 30}, {40, 50, 60},  {200, 100, 254},
                             {1, 2, 3}, {4, 5, 6},      {7, 8, 9},      {11, 12, 13}, {90, 181, 255}};
  for (int id = 0; id < 11; ++id)
    for (int c = 0; c < 3; ++c) t.polygon_colour[id][c] = UInt<8>(std::uint64_t(colour[id][c]));
  const int light_colour[3] = {250, 240, 230};
  for (int c = 0; c < 3; ++c) t.light_colour[3][c] = UInt<8>(std::uint64_t(light_colour[c]));
  const int z0 = 127 * 128;
  y_sorter_reset(*rig.mem, 16);
  const std::vector<Segment<P>> segs = {
      // Line 3: priority (A before B; both cover columns 5..9: A's), the tie rule at both ends, a
      // pixel half A half B (box filter 75.5 -> 76, id tie -> the earlier polygon), a pixel with 4
      // samples of polygon 10 over the background.
      columns(3, 0, 3, 0, 10, 128, z0, 1), columns(3, 0, 3, 5, 20, 128, z0, 2), columns(3, 1, 2, 20, 22, 64, z0, 10),
      // Line 6: screen door: the non-opaque polygon 3 takes the samples with (i + row) even, the
      // opaque polygon 4 behind it the others.
      columns(6, 0, 3, 0, 64, 255, z0, 3, false), columns(6, 0, 3, 0, 64, 100, z0, 4),
      // Line 9: fog: polygon 5 at the fogged depth: c I / 256 (1 - 1/4) + fog / 4.
      columns(9, 0, 3, 0, 64, 128, fog_code, 5),
      // Line 12, majority ids. Pixel 1: 7 samples of 9, 5 of 4, 4 background -> 9.
      columns(12, 0, 0, 4, 8, 10, z0, 9), columns(12, 1, 1, 4, 7, 10, z0, 9), columns(12, 1, 1, 7, 8, 10, z0, 4),
      columns(12, 2, 2, 4, 8, 10, z0, 4),
      // Pixel 2: 8 of 6, 8 of 2 -> 2 (tie: the earlier polygon). Pixel 3: 8 of 7, 8 background -> 7.
      columns(12, 0, 1, 8, 12, 10, z0, 6), columns(12, 2, 3, 8, 12, 10, z0, 2), columns(12, 0, 1, 12, 16, 10, z0, 7),
      // Pixel 4: 6 of 3, 6 of 1, 4 background -> 1.
      columns(12, 0, 0, 16, 20, 10, z0, 3), columns(12, 1, 1, 16, 18, 10, z0, 3), columns(12, 1, 1, 18, 20, 10, z0, 1),
      columns(12, 2, 2, 16, 20, 10, z0, 1),
      // Pixel 5: light 3 over the whole pixel, then polygon 8 on its two middle columns: the light's
      // colour everywhere, the id 8 (lights aside; 8 samples of 8 against 8 of none: the
      // background loses ties).
      columns(12, 0, 3, 20, 24, 255, z0, 3, true, true), columns(12, 0, 3, 21, 23, 10, z0, 8)};
  for (const auto& s : segs) ASSERT_TRUE(y_sort(s, *rig.mem));
  auto render = [&](int line) { return render_line(line, kLog2, *rig.mem, t, *rig.line, *rig.pixels); };
  const LineBuffer<P>& w = *rig.line;
  const PixelLine& px = *rig.pixels;

  ASSERT_EQ(render(3), 3);
  for (int r = 0; r < 4; ++r)
    for (int i = 0; i < 64; ++i) {
      const int owner = i < 10 ? 1 : i < 20 ? 2 : (i < 22 && r >= 1 && r <= 2) ? 10 : -1;
      ASSERT_EQ(w.polygon[r][i], owner) << r << " " << i;
      ASSERT_EQ(w.owned[r][i], owner >= 0);
      if (owner > 0) {
        for (int c = 0; c < 3; ++c)
          ASSERT_EQ(raw_of(w.rgb[r][i][c]), exact_sample(colour[owner][c], owner == 10 ? 64 : 128, 0, 0));
      }
    }
  EXPECT_EQ(px.rgb[0][0].value(), 100u);  // 200 * 128 / 256
  EXPECT_EQ(px.rgb[0][2].value(), 25u);
  EXPECT_EQ(px.id[0], 1);
  EXPECT_EQ(px.rgb[2][0].value(), 76u);  // (8 * 100 + 8 * 51) / 16 = 75.5, half up
  EXPECT_EQ(px.id[2], 1);
  EXPECT_EQ(px.id[3], 2);
  // Pixel 5: 4 samples of 90 * 64 / 256 = 22.5 and 12 of background 7: (90 + 84) / 16 = 10.875 -> 11.
  EXPECT_EQ(px.rgb[5][0].value(), 11u);
  EXPECT_EQ(px.id[5], -1);  // 4 samples of 10 against 12 of the background: most samples win
  EXPECT_EQ(px.rgb[6][1].value(), 8u);
  EXPECT_EQ(px.id[6], -1);

  ASSERT_EQ(render(6), 2);
  for (int r = 0; r < 4; ++r)
    for (int i = 0; i < 64; ++i) {
      const bool door_open = ((i + 4 * 6 + r) & 1) == 0;
      ASSERT_EQ(w.polygon[r][i], door_open ? 3 : 4);
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(raw_of(w.rgb[r][i][c]),
                  door_open ? exact_sample(colour[3][c], 255, 0, 0) : exact_sample(colour[4][c], 100, 0, 0));
    }
  for (int p = 0; p < 16; ++p) {
    EXPECT_EQ(px.id[p], 3);  // 8 and 8: the earlier polygon
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(i128(px.rgb[p][c].value()), round_half_up(8 * i128(exact_sample(colour[3][c], 255, 0, 0)) +
                                                              8 * i128(exact_sample(colour[4][c], 100, 0, 0)),
                                                          4096));
  }

  ASSERT_EQ(render(9), 1);
  for (int c = 0; c < 3; ++c) {
    const std::int64_t s = exact_sample(colour[5][c], 128, fog_f, fog[c]);
    EXPECT_EQ(raw_of(w.rgb[2][17][c]), s);
    EXPECT_EQ(i128(px.rgb[4][c].value()), round_half_up(16 * i128(s), 4096));
  }
  EXPECT_EQ(px.rgb[4][0].value(), 79u);  // 100 * 3/4 + 16 / 4
  EXPECT_EQ(px.rgb[4][1].value(), 46u);  // 50 * 3/4 + 32 / 4 = 45.5, half up

  ASSERT_EQ(render(12),
            int(std::count_if(segs.begin(), segs.end(), [](const Segment<P>& s) { return s.line.value() == 12; })));
  EXPECT_EQ(px.id[1], 9);
  EXPECT_EQ(px.id[2], 2);
  EXPECT_EQ(px.id[3], 7);
  EXPECT_EQ(px.id[4], 1);
  EXPECT_EQ(px.id[5], 8);
  EXPECT_EQ(px.id[0], -1);
  for (int r = 0; r < 4; ++r)
    for (int i = 20; i < 24; ++i) {
      ASSERT_TRUE(w.owned[r][i]);
      for (int c = 0; c < 3; ++c) ASSERT_EQ(raw_of(w.rgb[r][i][c]), exact_sample(light_colour[c], 255, 0, 0));
    }
  for (int c = 0; c < 3; ++c)
    EXPECT_EQ(i128(px.rgb[5][c].value()), round_half_up(16 * i128(light_colour[c]) * 255, 4096));
  // An empty line: the background.
  ASSERT_EQ(render(0), 0);
  for (int p = 0; p < 16; ++p) {
    EXPECT_EQ(px.id[p], -1);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(int(px.rgb[p][c].value()), bg[c]);
  }
}

// ---- Video channel: fixed against its double twin ----------------------------------------------------

struct RawSegment {
  int line = 0, rf = 0, rl = 0;
  std::int64_t xl[4] = {}, xr[4] = {};  // X raw (kFx fractional bits)
  std::int64_t il = 0, ir = 0;          // Intensity raw (kFi fractional bits)
  int zl = 0, zr = 0;                   // e8m7 codes
  int source = 0;
  bool light = false, opaque = true;
};

RawSegment random_raw_segment(Rng& rng, int line, int sources) {
  RawSegment s;
  s.line = line;
  s.light = below(rng, 8) == 0;
  s.opaque = s.light || below(rng, 4) != 0;
  s.rf = int(below(rng, 4));
  s.rl = s.light ? s.rf : int(between(rng, s.rf, 3));
  s.source = int(below(rng, sources));
  const std::int64_t one = std::int64_t(1) << kFx;
  const std::int64_t x0 = between(rng, -8 * one, 4100 * one);
  const std::int64_t drift = between(rng, -40 * one, 40 * one);
  const int mode = int(below(rng, 6));
  for (int r = s.rf; r <= s.rl; ++r) {
    s.xl[r] = x0 + drift * (r - s.rf) + between(rng, -one, one);
    // Widths: a few samples, the whole screen, empty or reversed, or below 1/256 unit (the
    // reciprocal saturates).
    const std::int64_t width = mode == 0   ? between(rng, -4 * one, 0)
                               : mode == 1 ? between(rng, 1, (one >> 8) + 1)
                               : mode == 2 ? between(rng, 0, 4200 * one)
                                           : between(rng, 0, 300 * one);
    s.xr[r] = std::min(s.xl[r] + width, 8000 * one);  // within X's range (+-2^13)
  }
  const std::int64_t imax = std::int64_t(256) << kFi;  // full intensity: I in [0, 256]
  s.il = below(rng, 4) == 0 ? (below(rng, 2) ? imax : 0) : below(rng, imax + 1);
  s.ir = s.light ? s.il : below(rng, 4) == 0 ? (below(rng, 2) ? imax : 0) : below(rng, imax + 1);
  const int e = int(between(rng, 120, 134));
  s.zl = e * 128 + int(below(rng, 128));
  const int de =
      below(rng, 6) == 0 ? int(between(rng, 13, 16)) : int(between(rng, -1, 1));  // beyond the 12 guard bits too
  s.zr = s.light ? s.zl : std::clamp(e + de, 0, 255) * 128 + int(below(rng, 128));
  return s;
}

Segment<P> fixed_segment(const RawSegment& r) {
  Segment<P> s;
  s.line = UInt<10>(std::uint64_t(r.line));
  s.type = UInt<3>(kSegMiddle);
  s.row_first = UInt<2>(std::uint64_t(r.rf));
  s.row_last = UInt<2>(std::uint64_t(r.rl));
  for (int k = 0; k < 4; ++k) {
    s.xl[k] = X::from_raw_value(r.xl[k]);
    s.xr[k] = X::from_raw_value(r.xr[k]);
  }
  s.il = Intensity::from_raw_value(std::uint64_t(r.il));
  s.ir = Intensity::from_raw_value(std::uint64_t(r.ir));
  s.zl = zcode(r.zl);
  s.zr = zcode(r.zr);
  s.source = UInt<16>(std::uint64_t(r.source));
  s.is_light = r.light;
  s.opaque = r.opaque;
  return s;
}

// The twin's segment: the exact values of the same fields.
Segment<Twin> twin_segment(const RawSegment& r) {
  Segment<Twin> s;
  s.line = UInt<10>(std::uint64_t(r.line));
  s.type = UInt<3>(kSegMiddle);
  s.row_first = UInt<2>(std::uint64_t(r.rf));
  s.row_last = UInt<2>(std::uint64_t(r.rl));
  for (int k = 0; k < 4; ++k) {
    s.xl[k] = std::ldexp(double(r.xl[k]), -kFx);
    s.xr[k] = std::ldexp(double(r.xr[k]), -kFx);
  }
  s.il = std::ldexp(double(r.il), -kFi);
  s.ir = std::ldexp(double(r.ir), -kFi);
  s.zl = zvalue(r.zl);
  s.zr = zvalue(r.zr);
  s.source = UInt<16>(std::uint64_t(r.source));
  s.is_light = r.light;
  s.opaque = r.opaque;
  return s;
}

struct FogSetting {
  double start = 0, end = 0;
  int colour[3] = {0, 0, 0};
};

// The bound on |fixed - twin| for one sample of segment r at column i, colour c and polygon (or
// light) colour level, in output LSB. Derivation, following draw_segment (video_channel.hpp) and
// the policy (segment_arith.hpp); the twin computes the same steps in double (errors < 2^-40):
//  * xlt, xrt: midpoints of X at the first and last covered rows, rounded half up to X (the fixed
//    values are known exactly from the raw sums: + LSB_X / 2 when the sum is odd, else exact);
//    span s = xrt - xlt and along a = X_i - xlt (exact in X) follow.
//  * t: fixed 1/s rounded to 24 fractional bits (|error| <= 2^-25; saturated when 1/s exceeds the
//    Reciprocal's 8 integer bits, s < 2^-8: then any t), times a, rounded to 16 bits (2^-17),
//    clamped to [0, 1] (and 0 when a <= 0 or s <= 0); the twin clamps a / s the same way. Clamping is
//    1-Lipschitz: dt <= |t*(fixed a, s) - t*(exact a, s)| + a 2^-25 + 2^-17, at most 1.
//  * I = il + (ir - il) t, rounded half up to Intensity: dI <= |ir - il| dt + LSB_I / 2.
//  * Z = zfloat_lerp_ratio: dZ <= |zr - zl| dt + E + 2^-8 (max(zl, zr) + E), E = U / 2 (+ U when the
//    exponents differ by more than 12), U = 2^(emax - 146) (judge_lerp's derivation, t in [0, 1]).
//  * fog factor: the host's table rounds f(code) to 8 fractional bits (2^-9), f is linear in Z with
//    slope 1 / (end - start) and clamped: df <= 2^-9 + dZ / (end - start), at most 1.
//  * colour x I rounded to 8 fractional bits: dS <= c dI / 256 + 2^-9.
//  * fog mix s (1 - f) + g f rounded to 8 fractional bits: dOut <= dS + |g - S_twin| df + 2^-9.
double sample_bound(const RawSegment& r, const Lattice& lat, int i, int level, int g, const FogSetting& fog) {
  const double lsb_x = std::ldexp(1.0, -kFx);
  auto mid = [&](std::int64_t a, std::int64_t b) {  // (exact, fixed)
    const double exact = std::ldexp(double(a) + double(b), -kFx - 1);
    return std::pair<double, double>{exact, exact + (((a + b) & 1) != 0 ? lsb_x / 2 : 0)};
  };
  const auto [xlt, fxlt] = mid(r.xl[r.rf], r.xl[r.rl]);
  const auto [xrt, fxrt] = mid(r.xr[r.rf], r.xr[r.rl]);
  const double xi = 0.5 * double(lat.half(i));
  const double s = xrt - xlt, fs = fxrt - fxlt, a = xi - xlt, fa = xi - fxlt;
  auto ideal = [](double along, double span) { return span > 0 && along > 0 ? std::min(1.0, along / span) : 0.0; };
  double dt = std::abs(ideal(fa, fs) - ideal(a, s)) + std::ldexp(1.0, -40);
  if (fs > 0 && fa > 0) dt += fa * std::ldexp(1.0, -25) + std::ldexp(1.0, -17);
  if (fs > 0 && fs <= std::ldexp(1.0, -8)) dt = 1;  // 1/s reaches the Reciprocal's top, 2^8: saturated
  dt = std::min(dt, 1.0);
  const double il = std::ldexp(double(r.il), -kFi), ir = std::ldexp(double(r.ir), -kFi);
  const double dI = std::abs(ir - il) * dt + std::ldexp(1.0, -kFi - 1) + std::ldexp(1.0, -40);
  const double zl = zvalue(r.zl), zr = zvalue(r.zr), zmax = std::max(zl, zr);
  const int el = r.zl >> 7, er = r.zr >> 7;
  const double U = std::ldexp(1.0, std::max(el, er) - 146);
  const double E = U / 2 + (std::abs(el - er) > 12 ? U : 0);
  const double dZ = std::abs(zr - zl) * dt + E + std::ldexp(zmax + E, -8) + std::ldexp(zmax, -40);
  const double df = std::min(1.0, std::ldexp(1.0, -9) + dZ / (fog.end - fog.start) + std::ldexp(1.0, -40));
  const double t = ideal(a, s);
  const double shade = level * (il + (ir - il) * t) / 256;  // the twin's colour x I
  const double dS = level * dI / 256 + std::ldexp(1.0, -9);
  return dS + std::abs(g - shade) * df + std::ldexp(1.0, -9) + std::ldexp(1.0, -30);
}

struct VideoStats {
  long samples = 0, pixels = 0, pixels_differ = 0;
  double worst_sample = 0, worst_sample_ratio = 0, worst_pixel_bound = 0;
};

// Random segments (lights, screen doors, empty and reversed spans, spans below 1/256 unit, X off the
// screen, I at the extremes, Z across binades) in random priority order, rendered by the fixed
// video channel and by its twin from the same values. Ownership and ids: EQUAL (the same X, the
// same decisions) and equal to an independent reference (first covering segment by the exact
// position rule and the screen door). Samples: within sample_bound. Pixels: the box filter averages
// 16 samples and rounds half up in both, so |fixed - twin| <= ceil(mean of the 16 bounds) (0 when
// every sample is the background, exact in both).
void work_video_twin(int scale, Digest* dg, VideoStats& st) {
  Rng rng(0x71DE0);
  for (int log2 = kMinRasterLog2; log2 <= kMinRasterLog2 + 2; ++log2)
    for (int trial = 0; trial < (3 * scale + 1) / 2; ++trial) {
      const Lattice lat(log2);
      const int n = lat.n, cols = lat.rows, sources = 24;
      VideoRig<P, 2048> fx;
      VideoRig<Twin, 2048> tw;
      FogSetting fog;
      const int c0 = int(between(rng, 124, 130)) * 128 + int(below(rng, 128));
      const int c1 = c0 + int(between(rng, 64, 600));
      fog.start = zvalue(c0);
      fog.end = zvalue(c1);
      for (int code = 0; code < (1 << 15); ++code) {  // the host's table (as the engine builds it)
        const double f = std::clamp((zvalue(code) - fog.start) / (fog.end - fog.start), 0.0, 1.0);
        fx.tables->fog.f[code] = P::FogFactor::from_raw_value(std::uint64_t(std::lround(f * 256)));
      }
      tw.tables->fog.start = fog.start;
      tw.tables->fog.end = fog.end;
      for (int c = 0; c < 3; ++c) {
        fog.colour[c] = int(below(rng, 256));
        const int bgc = int(below(rng, 256));
        fx.tables->fog_colour[c] = UInt<8>(std::uint64_t(fog.colour[c]));
        tw.tables->fog_colour[c] = fog.colour[c];
        fx.tables->background[c] = UInt<8>(std::uint64_t(bgc));
        tw.tables->background[c] = bgc;
        for (int id = 0; id < sources; ++id) {
          const int pc = int(below(rng, 256)), lc = int(below(rng, 256));
          fx.tables->polygon_colour[id][c] = UInt<8>(std::uint64_t(pc));
          tw.tables->polygon_colour[id][c] = pc;
          fx.tables->light_colour[id][c] = UInt<8>(std::uint64_t(lc));
          tw.tables->light_colour[id][c] = lc;
        }
      }
      y_sorter_reset(*fx.mem, n);
      y_sorter_reset(*tw.mem, n);
      std::vector<std::vector<RawSegment>> lines(static_cast<std::size_t>(n));
      for (int line = 0; line < n; ++line) {
        const int count = int(below(rng, 11));
        for (int k = 0; k < count; ++k) {
          const RawSegment r = random_raw_segment(rng, line, sources);
          lines[std::size_t(line)].push_back(r);
          ASSERT_TRUE(y_sort(fixed_segment(r), *fx.mem));
          ASSERT_TRUE(y_sort(twin_segment(r), *tw.mem));
        }
      }
      for (int line = 0; line < n; ++line) {
        const auto& segs = lines[std::size_t(line)];
        ASSERT_EQ(render_line(line, log2, *fx.mem, *fx.tables, *fx.line, *fx.pixels), int(segs.size()));
        ASSERT_EQ(render_line(line, log2, *tw.mem, *tw.tables, *tw.line, *tw.pixels), int(segs.size()));
        std::vector<double> bound(std::size_t(n) * 3, 0.0);  // per pixel and colour: the sum of sample bounds
        for (int r = 0; r < kRowsPerLine; ++r) {
          const int row = 4 * line + r;
          for (int i = 0; i < cols; ++i) {
            // The reference: the first segment covering the sample (left X <= X_i < right X on the
            // raw values, screen door (i + row) odd closed for non-opaque), and the first polygon.
            const i128 xi = lat.half(i) * (i128(1) << (kFx - 1));
            int owner = -1, polygon = -1;
            for (std::size_t k = 0; k < segs.size(); ++k) {
              const RawSegment& s = segs[k];
              if (r < s.rf || r > s.rl || xi < s.xl[r] || xi >= s.xr[r]) continue;
              if (!s.opaque && ((i + row) & 1) != 0) continue;
              if (owner < 0) owner = int(k);
              if (!s.light && polygon < 0) polygon = s.source;
            }
            ASSERT_EQ(fx.line->owned[r][i], owner >= 0) << "row " << row << " col " << i;
            ASSERT_EQ(tw.line->owned[r][i], owner >= 0);
            ASSERT_EQ(fx.line->polygon[r][i], polygon);
            ASSERT_EQ(tw.line->polygon[r][i], polygon);
            if (owner < 0) continue;
            const RawSegment& s = segs[std::size_t(owner)];
            for (int c = 0; c < 3; ++c) {
              const int level =
                  int((s.light ? fx.tables->light_colour : fx.tables->polygon_colour)[s.source][c].value());
              const double b = sample_bound(s, lat, i, level, fog.colour[c], fog);
              const double d = std::abs(value_of(fx.line->rgb[r][i][c]) - tw.line->rgb[r][i][c]);
              ASSERT_LE(d, b) << "row " << row << " col " << i << " colour " << c;
              st.worst_sample = std::max(st.worst_sample, d);
              st.worst_sample_ratio = std::max(st.worst_sample_ratio, d / b);
              bound[std::size_t(i / 4) * 3 + std::size_t(c)] += b / 16;
              if (dg) dg->add(std::uint64_t(raw_of(fx.line->rgb[r][i][c])));
            }
            ++st.samples;
          }
        }
        for (int p = 0; p < n; ++p) {
          ASSERT_EQ(fx.pixels->id[p], tw.pixels->id[p]) << "line " << line << " pixel " << p;
          for (int c = 0; c < 3; ++c) {
            const int d = std::abs(int(fx.pixels->rgb[p][c].value()) - int(tw.pixels->rgb[p][c].value()));
            const double b = bound[std::size_t(p) * 3 + std::size_t(c)];
            ASSERT_LE(d, int(std::ceil(b))) << "line " << line << " pixel " << p << " colour " << c << " bound " << b;
            st.pixels_differ += d != 0;
            st.worst_pixel_bound = std::max(st.worst_pixel_bound, b);
            if (dg) dg->add(fx.pixels->rgb[p][c].value());
          }
          if (dg) dg->add_signed(fx.pixels->id[p]);
          ++st.pixels;
        }
      }
    }
}

TEST(VideoChannel, FixedAgainstTwinPerSampleAndPixel) {
  VideoStats st;
  work_video_twin(kScale, nullptr, st);
  EXPECT_GT(st.samples, 20000);
  std::printf(
      "video channel: %ld samples, worst |fixed - twin| %.4f LSB (%.3f of its bound); %ld of %ld pixel "
      "values differ, pixel bound up to %.3f LSB\n",
      st.samples, st.worst_sample, st.worst_sample_ratio, st.pixels_differ, st.pixels * 3, st.worst_pixel_bound);
  RecordProperty("worst_sample_lsb", std::to_string(st.worst_sample));
  RecordProperty("worst_sample_of_bound", std::to_string(st.worst_sample_ratio));
  RecordProperty("pixel_values_differing", std::to_string(st.pixels_differ));
}

}  // namespace

// ---- The video half of SegmentKernels.Digest -------------------------------------------------------------

namespace segkernels {
void digest_video_half(kernel_test::Digest& d) {
  work_y_sorter<24>(1, &d);
  work_lights_through_video(1, &d);
  VideoStats st;
  work_video_twin(1, &d, st);
}
}  // namespace segkernels

}  // namespace cig::hls
