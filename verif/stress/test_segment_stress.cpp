// Stress tests of the segment processor through the engine interface (make_engine): polygon
// lists built in code with the hard cases of the segment generator (slivers, one-line-tall
// polygons, vertices at and beyond the clamp limits, vertical and horizontal edges, huge and
// sub-sample polygons, many polygons sharing vertices, overlaps) and memory overflows. Each scene
// runs on the bit-accurate engine in its default format and on its double twin, and is checked
// against the float reference with snapped vertices:
//
//  * coverage and ids: where the derived X error bound (stress_support.hpp) leaves no sample
//    uncertain, the engine's pixel values and ids equal the reference's exactly; elsewhere each
//    pixel differs by at most U x (largest level step) / 16 per channel (U uncertain samples).
//    Depth and priority never disagree in these scenes: every polygon has a constant depth that
//    grows with its position in the priority list, and light points are the nearest primitives
//    and rank first;
//  * the report equals a brute-force recount (area codes, segments per field and code, frame
//    memory words, overload threshold by exhaustive search, stored / lost segments);
//  * memory overflow is reported, never wrapped, and loses exactly what a first-fit frame memory
//    and a full segment bank must lose.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "registry/engine_registry.hpp"
#include "stress/stress_support.hpp"

namespace cig::stress {
namespace {

struct EngineCase {
  std::string label, engine;
  std::map<std::string, std::string> params;
  XErrorBound bound;
  std::string format;  // the format name the engine must report (the bound is derived for it)
};

// gtest prints parameters of failed tests with this.
void PrintTo(const EngineCase& c, std::ostream* os) { *os << c.label << " (" << c.engine << ")"; }

template <class Fmt>
EngineCase fixed_case(const std::string& label, const std::map<std::string, std::string>& params) {
  return {label, "segment", params, XErrorBound::fixed<Fmt>(), Fmt::name};
}
EngineCase default_segment() { return fixed_case<hls::SegmentFormatDefault>("fixed", {}); }
EngineCase twin() { return {"twin", "segment-double", {}, XErrorBound::double_twin(), "double"}; }

std::unique_ptr<RasterEngine> engine_for(const EngineCase& ec) {
  EngineOptions eo;
  eo.params = ec.params;
  return make_engine(ec.engine, eo);
}

std::string test_name() { return ::testing::UnitTest::GetInstance()->current_test_info()->name(); }

struct Checked {
  Agreement agreement;
  EngineRun run;
};

// Renders the frame with the engine and with the snapped reference, checks the pixels against the
// uncertainty bound and the report against the brute-force recount.
Checked check_scene(const ScreenFrame& frame, const EngineCase& ec) {
  EngineOptions ro;
  ro.snap = true;
  Checked c{Agreement(), engine_for(ec)->render(frame)};
  const EngineRun want = make_engine("float", ro)->render(frame);
  EXPECT_EQ(c.run.report.at("format").get<std::string>(), ec.format) << "the bound is derived for another format";
  c.agreement = compare_with_reference(frame, c.run.out, want.out, uncertain_samples(frame, ec.bound));
  EXPECT_EQ(c.agreement.violations, 0) << ec.label << ": " << c.agreement.first_violation;
  expect_report_matches(c.run.report, frame, count_frame(frame));
  std::cout << "[ stress   ] " << test_name() << " " << ec.label << ": " << c.agreement.summary() << "\n";
  return c;
}

// Strictly convex hull (Andrew's monotone chain), counter-clockwise, collinear points dropped.
std::vector<GridVertex> hull(std::vector<GridVertex> pts) {
  auto cross = [](const GridVertex& o, const GridVertex& a, const GridVertex& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  std::sort(pts.begin(), pts.end(),
            [](const GridVertex& a, const GridVertex& b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  pts.erase(std::unique(pts.begin(), pts.end(),
                        [](const GridVertex& a, const GridVertex& b) { return a.x == b.x && a.y == b.y; }),
            pts.end());
  if (pts.size() < 3) return pts;
  std::vector<GridVertex> h(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
    h[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(h[k - 2], h[k - 1], pts[i - 1]) <= 0) --k;
    h[k++] = pts[i - 1];
  }
  h.resize(k - 1);
  return h;
}

// A random convex polygon of up to 16 vertices around (cx, cy), extent about r grid units.
std::vector<GridVertex> random_convex(Rng& rng, long cx, long cy, long r) {
  const long a = between(rng, -1024, 1024), b = between(rng, -1024, 1024);
  const long c = between(rng, -1024, 1024), d = between(rng, -1024, 1024);
  std::vector<GridVertex> pts;
  const long m = between(rng, 3, 24);
  for (long k = 0; k < m; ++k) {  // clamped before the hull: the formatter's clamp keeps it convex
    const long u = between(rng, -1024, 1024), v = between(rng, -1024, 1024);
    pts.push_back({std::clamp(cx + r * (a * u + b * v) / (1024 * 1024), 0L, 4095L),
                   std::clamp(cy + r * (c * u + d * v) / (1024 * 1024), 0L, 4095L)});
  }
  std::vector<GridVertex> h = hull(pts);
  if (h.size() < 3) h = std::vector<GridVertex>{{cx, cy}, {cx + 3, cy}, {cx, cy + 3}};
  if (h.size() > 16) {
    std::vector<GridVertex> sub;
    for (std::size_t k = 0; k < 16; ++k) sub.push_back(h[k * h.size() / 16]);
    h = sub;
  }
  if (below(rng, 2)) std::reverse(h.begin(), h.end());  // either winding
  return h;
}

// Every polygon of the frame stays convex (or degenerate) after the formatter's clamping: the
// scenes below must mean what they say.
void expect_snapped_convex(const ScreenFrame& frame) {
  for (std::size_t i = 0; i < frame.polygons.size(); ++i) {
    const PolygonCount c = count_polygon(frame.polygons[i], Lattice{frame.raster});
    int sign = 0;
    const std::size_t n = c.v.size();
    for (std::size_t k = 0; k < n; ++k) {
      const GridVertex &a = c.v[k], &b = c.v[(k + 1) % n], &e = c.v[(k + 2) % n];
      const long t = (b.x - a.x) * (e.y - b.y) - (b.y - a.y) * (e.x - b.x);
      if (t == 0) continue;
      if (sign == 0) sign = t > 0 ? 1 : -1;
      ASSERT_EQ(sign, t > 0 ? 1 : -1) << "polygon " << i << " is not convex after clamping";
    }
  }
}

// ---- Scenes -----------------------------------------------------------------------------------

// Long thin triangles, thin parallelograms of every slope, near-horizontal slivers and needles.
ScreenFrame sliver_scene() {
  Rng rng(101);
  ScreenFrame f = empty_frame(512, {0, 0, 0});
  for (long k = 0; k < 160; ++k) {
    const long x = between(rng, 0, 4095), y = between(rng, 0, 4095);
    const long qx = between(rng, 0, 4095), qy = between(rng, 0, 4095);
    const long w = between(rng, 1, 6);
    // A long thin triangle, a thin parallelogram, a near-horizontal sliver, a needle.
    std::vector<GridVertex> v;
    if (k % 4 == 0) v = std::vector<GridVertex>{{x, y}, {x + w, y}, {qx, qy}};
    if (k % 4 == 1) v = std::vector<GridVertex>{{x, y}, {x + w, y}, {qx + w, qy}, {qx, qy}};
    if (k % 4 == 2) v = std::vector<GridVertex>{{x, y}, {qx, y + w / 3}, {qx, y + w / 3 + w}, {x, y + w}};
    if (k % 4 == 3) v = std::vector<GridVertex>{{x, y}, {qx, qy}, {(x + qx) / 2 + 1, (y + qy) / 2}};
    for (auto& p : v) p = {std::clamp(p.x, 0L, 4095L), std::clamp(p.y, 0L, 4095L)};
    f.polygons.push_back(grid_polygon(v, 10.0 + double(k), level_for(k)));
  }
  return f;
}

// Polygons at most about one raster line tall, at every offset of their top within the line (lines
// span [8L - 1, 8L + 7), sample rows at 8L + 0, 2, 4, 6) and heights 1..9 units: rectangles,
// flat-topped triangles, slanted parallelograms (slope 3, exact) and very slanted ones.
ScreenFrame one_line_scene() {
  ScreenFrame f = empty_frame(512, {16, 16, 16});
  long k = 0;
  for (long o = 0; o < 8; ++o)
    for (long h = 1; h <= 9; ++h, ++k) {
      const long line = 5 + 7 * k, y0 = 8 * line - 1 + o, y1 = y0 + h;
      const long x = 40 + 11 * k % 97;
      const std::vector<std::vector<GridVertex>> shapes = {
          {{x, y0}, {x + 37 + k, y0}, {x + 37 + k, y1}, {x, y1}},
          {{x + 300, y0}, {x + 520, y0}, {x + 390 + k % 7, y1}},
          {{x + 700, y0}, {x + 850, y0}, {x + 850 + 3 * h, y1}, {x + 700 + 3 * h, y1}},
          {{x + 1100, y0}, {x + 1140, y0}, {x + 2140, y1}, {x + 2100, y1}},
          {{x + 2400, y0}, {x + 2403, y1}, {x + 2398, y1}},
      };
      for (const auto& s : shapes) {
        f.polygons.push_back(grid_polygon(s, 10.0 + double(f.polygons.size()), level_for(long(f.polygons.size()))));
      }
    }
  return f;
}

// Vertices at the clamp limits (0 and 4095) and beyond the screen on every side, clamped by the
// formatter; polygons wholly off screen (clamped to zero area); a full-screen polygon behind all.
ScreenFrame clamp_scene(int raster) {
  ScreenFrame f = empty_frame(raster, {32, 0, 48});
  const std::vector<std::vector<GridVertex>> shapes = {
      {{0, 0}, {300, 0}, {0, 300}},                                    // corner at the origin
      {{4095, 4095}, {3800, 4095}, {4095, 3800}},                      // corner at 4095, 4095
      {{-1000, -1000}, {700, -50}, {-50, 700}},                        // beyond the corner: clamped to (0, 0)
      {{4095, 0}, {4095, 500}, {3700, 250}},                           // vertical edge on X = 4095
      {{0, 4095}, {500, 4095}, {250, 3650}},                           // horizontal edge on Y = 4095
      {{-100, 900}, {40, 900}, {40, 3000}, {-100, 3000}},              // strip beyond the left edge
      {{4050, 900}, {9000, 900}, {9000, 3000}, {4050, 3000}},          // strip beyond the right edge
      {{900, -300}, {3000, -300}, {3000, 41}, {900, 41}},              // beyond the top
      {{900, 4060}, {3000, 4060}, {3000, 4600}, {900, 4600}},          // beyond the bottom
      {{100, 1500}, {7000, 1800}, {300, 2600}},                        // one vertex far right
      {{1500, 1000}, {2600, -5000}, {2700, 1200}},                     // one vertex far above
      {{2047, 2047}, {2047 + 2048000, 2047}, {2047, 2047 + 2048000}},  // Xs = Ys = 1001: far beyond
      {{-300, -300}, {-100, -300}, {-200, -100}},                      // wholly off screen: zero area
      {{4200, 100}, {4500, 100}, {4300, 400}},                         // wholly off screen at X = 4095
      {{1000, 5000}, {1200, 5200}, {900, 5300}},                       // wholly below: zero area
      {{-5000, -5000}, {9000, -5000}, {9000, 9000}, {-5000, 9000}},    // the whole screen, behind all
  };
  for (std::size_t k = 0; k < shapes.size(); ++k)
    f.polygons.push_back(grid_polygon(shapes[k], 10.0 + double(k), level_for(long(k))));
  return f;
}

// Vertical and horizontal edges at every offset from the sample columns and rows (even offsets lie
// ON samples: the tie rule decides), diamonds (slope 1) and triangles of slopes 2 and 1/2: every
// crossing is exact in every format, so the engine must equal the reference exactly.
ScreenFrame axis_scene() {
  ScreenFrame f = empty_frame(512, {0, 0, 0});
  // In front: overlapping rectangles and diamonds (smaller depth, earlier in the list).
  for (long k = 0; k < 12; ++k) {
    const long x0 = 137 + 301 * k + k % 8, y0 = 211 + 293 * ((k * 5) % 12) + (k * 3) % 8;
    f.polygons.push_back(grid_polygon({{x0, y0}, {x0 + 405 + k, y0}, {x0 + 405 + k, y0 + 333 - k}, {x0, y0 + 333 - k}},
                                      10.0 + double(f.polygons.size()), level_for(k)));
    const long cx = 250 + 300 * k + k % 8, cy = 3800 - 290 * k - k % 8, r = 60 + 17 * k;
    f.polygons.push_back(grid_polygon({{cx, cy - r}, {cx + r, cy}, {cx, cy + r}, {cx - r, cy}},
                                      10.0 + double(f.polygons.size()), level_for(k + 3)));
    const long t = 40 + 9 * k;  // slopes 2 and 1/2
    f.polygons.push_back(grid_polygon({{cx + 200, cy}, {cx + 200 + 2 * t, cy + t}, {cx + 200, cy + 2 * t}},
                                      10.0 + double(f.polygons.size()), level_for(k + 5)));
    f.polygons.push_back(
        grid_polygon({{cx - 120, cy - 240}, {cx - 120 + t, cy - 240 + 2 * t}, {cx - 120 - t, cy - 240 + 2 * t}},
                     10.0 + double(f.polygons.size()), level_for(k + 6)));
  }
  // Behind: a 16 x 16 grid of non-overlapping rectangles, edges at every offset modulo 8.
  for (long i = 0; i < 16; ++i)
    for (long j = 0; j < 16; ++j) {
      const long x0 = 256 * i + (i + j) % 8, y0 = 256 * j + (i + 2 * j) % 8;
      const long x1 = x0 + 200 + (3 * i + j) % 8 + 8 * (j % 4), y1 = y0 + 190 + (i + 5 * j) % 8;
      f.polygons.push_back(grid_polygon({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, 10.0 + double(f.polygons.size()),
                                        level_for(i * 16 + j)));
    }
  return f;
}

// Huge polygons (beyond the screen, clamped) and tiny ones: triangles of 1..3 units (most cover no
// sample, some exactly one), unit squares on and off the sample lattice; a full-screen background.
ScreenFrame huge_tiny_scene() {
  Rng rng(202);
  ScreenFrame f = empty_frame(512, {0, 0, 0});
  for (long k = 0; k < 600; ++k) {
    const long x = between(rng, 0, 4092), y = between(rng, 0, 4092);
    std::vector<GridVertex> v;
    if (k % 3 == 0) v = std::vector<GridVertex>{{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}};
    else
      v = std::vector<GridVertex>{
          {x, y}, {x + between(rng, 1, 3), y + between(rng, 0, 3)}, {x + between(rng, 0, 2), y + between(rng, 1, 3)}};
    f.polygons.push_back(grid_polygon(v, 10.0 + double(k), level_for(k)));
  }
  f.polygons.push_back(grid_polygon({{-3000, -2000}, {9000, 500}, {2000, 9000}}, 1000, {112, 16, 48}));
  f.polygons.push_back(grid_polygon({{-100, 3000}, {5000, -4000}, {6000, 6000}}, 1001, {16, 96, 64}, false));
  f.polygons.push_back(grid_polygon({{0, 0}, {4095, 0}, {4095, 4095}, {0, 4095}}, 2000, {48, 48, 48}));
  return f;
}

// A conforming triangulation of the whole screen on a jittered 20 x 20 grid (corners at 0 and
// 4095, shared vertices and edges everywhere, slivers where the jitter is large). Every tile has
// green level 112 over a black background, so a crack (a sample no tile covers) shows as a pixel
// with less green.
ScreenFrame tiling_scene() {
  Rng rng(303);
  ScreenFrame f = empty_frame(512, {0, 0, 0});
  constexpr long kCells = 20;
  std::vector<GridVertex> grid((kCells + 1) * (kCells + 1));
  for (long j = 0; j <= kCells; ++j)
    for (long i = 0; i <= kCells; ++i) {
      long x = 4095 * i / kCells, y = 4095 * j / kCells;
      if (i > 0 && i < kCells) x += between(rng, -90, 90);
      if (j > 0 && j < kCells) y += between(rng, -90, 90);
      grid[std::size_t(j * (kCells + 1) + i)] = {x, y};
    }
  auto at = [&](long i, long j) { return grid[std::size_t(j * (kCells + 1) + i)]; };
  for (long j = 0; j < kCells; ++j)
    for (long i = 0; i < kCells; ++i) {
      const GridVertex a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      const bool diagonal = below(rng, 2) == 0;
      const std::vector<std::vector<GridVertex>> tris =
          diagonal ? std::vector<std::vector<GridVertex>>{{a, b, c}, {a, c, d}}
                   : std::vector<std::vector<GridVertex>>{{a, b, d}, {b, c, d}};
      for (const auto& t : tris) {
        const long k = long(f.polygons.size());
        f.polygons.push_back(
            grid_polygon(t, 10.0 + double(k), {int(16 * (1 + k % 7)), 112, int(16 * (1 + (k / 7) % 7))}));
      }
    }
  return f;
}

// A fan: 128 triangles around one shared centre vertex, their outer vertices on the border of the
// square [447, 3647]^2, tiling it.
ScreenFrame fan_scene() {
  ScreenFrame f = empty_frame(512, {0, 0, 0});
  std::vector<GridVertex> ring;
  for (long k = 0; k < 32; ++k) ring.push_back({447 + 100 * k, 447});
  for (long k = 0; k < 32; ++k) ring.push_back({3647, 447 + 100 * k});
  for (long k = 0; k < 32; ++k) ring.push_back({3647 - 100 * k, 3647});
  for (long k = 0; k < 32; ++k) ring.push_back({447, 3647 - 100 * k});
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const long id = long(k);
    f.polygons.push_back(grid_polygon({{2047, 2047}, ring[k], ring[(k + 1) % ring.size()]}, 10.0 + double(k),
                                      {int(16 * (1 + id % 7)), 112, int(16 * (1 + (id / 7) % 7))}));
  }
  return f;
}

// Random convex polygons of every size overlapping, a fifth of them screen-door transparent, with
// depth growing along the priority list; light points in front of everything, ranked first.
ScreenFrame overlap_scene() {
  Rng rng(404);
  ScreenFrame f = empty_frame(512, {0, 32, 64});
  for (long k = 0; k < 260; ++k) {
    const long r = k % 5 == 0 ? between(rng, 600, 2500) : k % 5 == 1 ? between(rng, 100, 600) : between(rng, 4, 100);
    f.polygons.push_back(grid_polygon(random_convex(rng, between(rng, 0, 4095), between(rng, 0, 4095), r),
                                      10.0 + double(k), level_for(k), below(rng, 5) != 0));
  }
  for (long k = 0; k < 40; ++k)
    f.light_points.push_back(
        grid_light(between(rng, 0, 4095), between(rng, 0, 4095), int(k % 8), 1.0, level_for(k + 11), 0));
  return f;
}

// ---- Scene tests on the default fixed format and on the twin ------------------------------------

class SegmentStress : public ::testing::TestWithParam<EngineCase> {};

TEST_P(SegmentStress, Slivers) { check_scene(sliver_scene(), GetParam()); }

TEST_P(SegmentStress, OneLineTall) {
  const ScreenFrame f = one_line_scene();
  // The scene is what it says: every polygon crosses at most two lines, some no sample row at all.
  const FrameCount c = count_frame(f);
  EXPECT_GT(c.degenerate, 0);
  for (const auto& p : c.polygons) EXPECT_LE(p.last_line - p.first_line, 1);
  check_scene(f, GetParam());
}

TEST_P(SegmentStress, ClampLimits) {
  for (int raster : {16, 512, 1024}) {
    SCOPED_TRACE("raster " + std::to_string(raster));
    const ScreenFrame f = clamp_scene(raster);
    expect_snapped_convex(f);
    const FrameCount c = count_frame(f);
    // The wholly off-screen polygons clamp to zero area and are degenerate.
    for (std::size_t k : {12, 13, 14}) EXPECT_FALSE(c.polygons[k].valid) << k;
    check_scene(f, GetParam());
  }
}

TEST_P(SegmentStress, VerticalHorizontalAndExactSlopes) {
  const Agreement a = check_scene(axis_scene(), GetParam()).agreement;
  // Every crossing is exact, so the bound leaves nothing uncertain and the images are equal.
  EXPECT_EQ(a.samples_uncertain, 0);
  EXPECT_EQ(a.values_differ, 0);
  EXPECT_EQ(a.ids_differ, 0);
}

TEST_P(SegmentStress, HugeAndTiny) {
  const ScreenFrame f = huge_tiny_scene();
  expect_snapped_convex(f);
  check_scene(f, GetParam());
}

// Shared edges are computed from the same endpoints in both neighbours and covered half-open
// ([left X, right X)), so a tiling leaves no crack whatever the rounding of X.
void expect_watertight(const EngineRun& run, const EngineCase& ec, int x0, int x1) {
  long cracked = 0;
  for (int py = x0; py < x1; ++py)
    for (int px = x0; px < x1; ++px) cracked += run.out.image.at(px, py)[1] != 112;
  EXPECT_EQ(cracked, 0) << ec.label << ": pixels inside the tiling with a sample no tile covers";
}

TEST_P(SegmentStress, SharedVerticesTiling) {
  expect_watertight(check_scene(tiling_scene(), GetParam()).run, GetParam(), 0, 512);
}

TEST_P(SegmentStress, SharedVerticesFan) {
  // Pixels 56..455 lie wholly inside the square: pixel p spans [8p - 1, 8p + 7).
  expect_watertight(check_scene(fan_scene(), GetParam()).run, GetParam(), 56, 456);
}

TEST_P(SegmentStress, OverlapsOrderedInDepthAndPriority) { check_scene(overlap_scene(), GetParam()); }

INSTANTIATE_TEST_SUITE_P(Engines, SegmentStress, ::testing::Values(default_segment(), twin()),
                         [](const ::testing::TestParamInfo<EngineCase>& i) { return i.param.label; });

// The exact scene in the other fixed formats (the default one runs above): the bound is zero for
// every format's widths, so the images must be equal.
TEST(SegmentStressFormats, ExactSlopesEveryFormat) {
  const ScreenFrame f = axis_scene();
  const std::vector<EngineCase> formats = {
      fixed_case<hls::SegmentFormatCoarse>("coarse", {{"format", "coarse"}}),
      fixed_case<hls::SegmentFormatMedium>("medium", {{"format", "medium"}}),
  };
  for (const auto& ec : formats) {
    const Agreement a = check_scene(f, ec).agreement;
    EXPECT_EQ(a.samples_uncertain, 0) << ec.label;
    EXPECT_EQ(a.values_differ, 0) << ec.label;
  }
}

// ---- Memory overflow ------------------------------------------------------------------------------

// More polygons than the frame memory holds (16K words): polygons that do not fit are counted and
// not drawn, the others are written first fit in list order (a large polygon that does not fit can
// be followed by smaller ones that do). The recount simulates exactly that.
TEST_P(SegmentStress, FrameMemoryOverflow) {
  Rng rng(505);
  ScreenFrame f = empty_frame(256, {0, 0, 0});
  for (long k = 0; k < 5200; ++k) {
    const long x = between(rng, 20, 4000), y = between(rng, 20, 4000);
    if (k % 50 == 49) {  // a 16-gon (up to 17 words): radius 32, vertices every 22.5 degrees
      std::vector<GridVertex> v;
      const long c16[16] = {32, 30, 23, 12, 0, -12, -23, -30, -32, -30, -23, -12, 0, 12, 23, 30};
      for (int q = 0; q < 16; ++q) v.push_back({x + 32 + c16[q], y + 32 + c16[(q + 12) % 16]});
      f.polygons.push_back(grid_polygon(v, 10.0 + double(k), level_for(k)));
    } else {
      f.polygons.push_back(grid_polygon({{x, y},
                                         {x + between(rng, 20, 60), y + between(rng, 10, 40)},
                                         {x + between(rng, 0, 20), y + between(rng, 50, 80)}},
                                        10.0 + double(k), level_for(k)));
    }
  }
  expect_snapped_convex(f);
  const FrameCount c = count_frame(f);
  ASSERT_GT(c.overflowed, 0) << "the scene must overflow the frame memory";
  EXPECT_LE(c.words, kFrameBankWords);
  // The reference draws every polygon, the engine only those written: compare the report and the
  // ids, not the image.
  const EngineRun run = engine_for(GetParam())->render(f);
  expect_report_matches(run.report, f, c);
  long shown = 0;
  for (std::int32_t id : run.out.ids.id) shown += id >= 0 && !c.written[std::size_t(id)];
  EXPECT_EQ(shown, 0);
}

// Protected polygons alone overflow both segment banks: T = 0, every unprotected polygon is
// dropped, each bank holds exactly 48K segments and the rest are counted as lost, never wrapped
// over stored ones. The Y sorter receives segments in priority order (light points ranked first,
// then each polygon top line first) and a full bank refuses the rest: strip i (a protected strip
// of the full height, pixels 2i + 1 and 2i + 2) shows on line L exactly when its segment was
// stored, simulated here segment by segment.
TEST_P(SegmentStress, SegmentMemoryOverflowProtected) {
  ScreenFrame f = empty_frame(512, {0, 0, 0});
  constexpr long kStrips = 220;
  for (long i = 0; i < kStrips; ++i)
    f.polygons.push_back(grid_polygon({{16 * i + 7, 0}, {16 * i + 23, 0}, {16 * i + 23, 4095}, {16 * i + 7, 4095}},
                                      10.0 + double(i), level_for(i), true, true));
  for (long k = 0; k < 30; ++k) {  // unprotected, right of the strips: dropped
    const long x = 3700 + 12 * (k % 30), y = 100 + 130 * k;
    f.polygons.push_back(grid_polygon({{x, y}, {x + 9, y}, {x + 4, y + 40}}, 500.0 + double(k), level_for(k)));
  }
  for (long k = 0; k < 25; ++k) f.light_points.push_back(grid_light(3650, 60 + 160 * k, 7, 1.0, {112, 112, 112}, 0));
  const FrameCount c = count_frame(f);
  ASSERT_FALSE(c.fits(0)) << "the protected strips must overflow a bank on their own";
  EXPECT_EQ(c.threshold, 0);
  EXPECT_GT(c.dropped_memory_full, 0);

  const EngineRun run = engine_for(GetParam())->render(f);
  expect_report_matches(run.report, f, c);
  EXPECT_EQ(num(run.report.at("segments").at("stored_even")), kSegmentBankWords);
  EXPECT_EQ(num(run.report.at("segments").at("stored_odd")), kSegmentBankWords);
  EXPECT_EQ(num(run.report.at("overload").at("polygons_dropped")), 30);

  // Arrival order: the lights (priority 0), then strip by strip, line by line.
  const Lattice g{f.raster};
  long used[2] = {0, 0};
  for (const auto& l : f.light_points)
    for (long line : light_segment_lines(l, g)) ++used[line & 1];
  long wrong = 0;
  for (long i = 0; i < kStrips; ++i)
    for (long line = 0; line < f.raster; ++line) {
      const bool stored = used[line & 1] < kSegmentBankWords;
      used[line & 1] += stored;
      for (int px : {int(2 * i + 1), int(2 * i + 2)}) {
        const std::int32_t id = run.out.ids.id[std::size_t(line) * std::size_t(f.raster) + std::size_t(px)];
        wrong += id != (stored ? std::int32_t(i) : -1);
      }
    }
  EXPECT_EQ(wrong, 0) << "pixels showing a strip whose segment was lost, or missing one that was stored";
}

// Limits: more polygons than the 16-bit ids, or a raster outside 16..1024, are input errors.
TEST_P(SegmentStress, LimitsAreInputErrors) {
  ScreenFrame f = empty_frame(64, {0, 0, 0});
  f.polygons.assign(65537, grid_polygon({{0, 0}, {8, 0}, {0, 8}}, 10.0, {16, 16, 16}));
  auto engine = engine_for(GetParam());
  EXPECT_THROW(engine->render(f), InputError);
  ScreenFrame big = empty_frame(2048, {0, 0, 0});
  big.polygons.push_back(grid_polygon({{0, 0}, {8, 0}, {0, 8}}, 10.0, {16, 16, 16}));
  EXPECT_THROW(engine->render(big), InputError);
  // The same engine still works after rejecting frames.
  const ScreenFrame ok = clamp_scene(64);
  expect_report_matches(engine->render(ok).report, ok, count_frame(ok));
}

}  // namespace
}  // namespace cig::stress
