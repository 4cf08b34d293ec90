// Seed 004's architectures (SPEC E): the eq. 1 parser, eq. 10's PE counts, the window counts of
// eq. 2-3 measured with the setup and PE kernels, and the cycle model (quad::ArchModel) on cases
// small enough to derive by hand. cmodel/studies/arch_analysis.hpp holds the code under test;
// docs/results/architecture.md the discussion.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "hls/quadtree/mask_memory.hpp"
#include "hls/quadtree/pe.hpp"
#include "quadtree/arch_model.hpp"
#include "quadtree/architecture.hpp"
#include "studies/arch_analysis.hpp"

namespace cig::quad {
namespace {

// ---- eq. 1: the parser ------------------------------------------------------------------------

std::string stages_of(const Architecture& a) {
  std::string s;
  for (const ArchStage& st : a.stages)
    s += std::string(1, st.kind) + std::to_string(st.first_level) + "-" + std::to_string(st.last_level) + " ";
  return s;
}

TEST(ArchitectureParse, AcceptsTheSeedsExamples) {
  EXPECT_EQ(stages_of(Architecture::parse("8p2t", 10)), "p1-1 p2-2 p3-3 p4-4 p5-5 p6-6 p7-7 p8-8 t9-10 ");
  EXPECT_EQ(Architecture::parse("8p2t", 10).text, "8p2t");
  EXPECT_EQ(stages_of(Architecture::parse("9s1p", 10)), "s1-9 p10-10 ");
  // The seed's 3s1 3s2 2s3 2t: three stacks and a two-level tree; spaces are allowed.
  EXPECT_EQ(stages_of(Architecture::parse("3s 3s 2s 2t", 10)), "s1-3 s4-6 s7-8 t9-10 ");
  EXPECT_EQ(Architecture::parse("3s_3s_2s_2t", 10).text, "3s3s2s2t");
  // "n" is every remaining level: np, ns, nt at any raster.
  EXPECT_EQ(Architecture::parse("np", 9).text, "9p");
  EXPECT_EQ(Architecture::parse("np", 9).stages.size(), 9u);
  EXPECT_EQ(stages_of(Architecture::parse("ns", 9)), "s1-9 ");
  EXPECT_EQ(stages_of(Architecture::parse("nt", 4)), "t1-4 ");
  EXPECT_EQ(stages_of(Architecture::parse("4snp", 10)), "s1-4 p5-5 p6-6 p7-7 p8-8 p9-9 p10-10 ");
  EXPECT_EQ(Architecture::parse("4snp", 10).text, "4s6p");
}

void expect_rejected(const std::string& text, int n, const std::string& rule) {
  try {
    Architecture::parse(text, n, "--archs");
    ADD_FAILURE() << "'" << text << "' at n = " << n << " was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("--archs"), std::string::npos) << what;
    EXPECT_NE(what.find(rule), std::string::npos) << "'" << text << "': " << what;
  }
}

TEST(ArchitectureParse, RejectsBrokenRules) {
  expect_rejected("9p", 10, "cover 9 levels");  // the levels must add up to n
  expect_rejected("8p2t", 9, "cover more than the n = 9");
  expect_rejected("11p", 10, "cover more than");
  expect_rejected("2t8p", 10, "must be the last stage");  // t only last
  expect_rejected("nt1p", 10, "must be the last stage");
  expect_rejected("5x5p", 10, "unknown stage kind 'x'");
  expect_rejected("5p5", 10, "must be followed by s");
  expect_rejected("p", 10, "expected a count");
  expect_rejected("0p10p", 10, "at least one level");
  expect_rejected("", 10, "empty");
  expect_rejected("   ", 10, "empty");
}

// ---- eq. 10 -----------------------------------------------------------------------------------

TEST(ArchitecturePeCount, EqualsEq10AndTheSeedsTable) {
  const std::vector<SeedPeRow> rows = seed_pe_table();
  ASSERT_EQ(rows.size(), 10u);
  for (const SeedPeRow& r : rows) {
    // eq. 10 written out: i - 1 pipeline PEs and a (n - i + 1)-level tree of 1 + 4 + ... PEs.
    long long tree = 0;
    for (int k = 0; k < 10 - r.i + 1; ++k) tree += 1LL << (2 * k);
    EXPECT_EQ(r.formula, r.i - 1 + tree) << r.arch;
    EXPECT_EQ(r.formula, seed_pe_count(10, r.i)) << r.arch;
    EXPECT_EQ(Architecture::parse(r.arch, 10).pe_count(), r.formula) << r.arch;
    // The seed prints 4 significant digits.
    EXPECT_NEAR(round_significant(double(r.formula), 4), r.seed_printed, 1e-9 * r.seed_printed) << r.arch;
  }
  EXPECT_EQ(rows[1].arch, "1p9t");
  EXPECT_EQ(rows[1].formula, 87382);  // not the digest's 87,381: that is the tree alone
  EXPECT_EQ(rows[2].formula, 21847);
  EXPECT_EQ(rows[9].arch, "10p");
  EXPECT_EQ(Architecture::parse("9s1p", 10).pe_count(), 2);
  EXPECT_EQ(Architecture::parse("3s3s2s2t", 10).pe_count(), 3 + 5);  // the seed: "8 PEs instead of 13"
}

// ---- eq. 2-3: windows per level ---------------------------------------------------------------

// Statistical tolerance of a measured mean against its expectation: 4 standard errors (a normal
// deviate beyond 4 sigma has probability 6e-5), plus 1/K for the counts' granularity when every
// draw gives the same count (se = 0) while the expectation lies a fraction of a window away.
double tolerance(const LevelWindows& lw, int positions) { return 4 * lw.mean_se + 1.0 / positions; }

// Where eq. 2 holds (derivation; arch_analysis.hpp, rect_overlap_area). The setup gives a
// rectangle's edge tests every separating axis of the rectangle and a window's sample box (its own
// edge normals, and x and y: its own edges when axis-aligned, bounding-box edges when turned), so
// at levels 1..n-1 a window passes exactly when its sample box (a = alpha_l P pixels a side,
// P = 2^(n-l)) meets the rectangle. Over continuous translations the mean is then the area of the
// Minkowski sum in windows, E_area = S/P^2 + alpha_l (W + H)/P + alpha_l^2, W x H the extents, at
// any rotation. Eq. 2 at alpha = beta is S/P^2 + alpha_l L sqrt(2 pi S)/P + alpha_l^2, so
//   bound - E_area = alpha_l/P (L sqrt(2 pi S) - (W + H)) >= 0  <=>  L_shape = (W + H)/sqrt(2 pi S) <= L:
// every rectangle whose own shape factor is at most the seed's L = 1.514 meets eq. 2, whatever its
// rotation, with equality when L_shape = L. The positions drawn lie on the formatter grid, where the
// mean is E_cons = E_area + the closed box edges' boundary term (rect_grid_excess, Pick's theorem:
// 0 axis-aligned, (2 sigma - 1)/(g P)^2 at 45 degrees and n = 9); the measured mean must match
// E_cons within the statistical tolerance. At the pixel level the PE tests the 16 samples, a
// subset of the box, so the mean there is at most E_cons.
void expect_within_eq2(const WindowTable& t, int positions) {
  const TestRect& r = t.rect;
  const int n = r.raster_log2;
  for (int l = 1; l <= n; ++l) {
    const LevelWindows& lw = t.level[std::size_t(l)];
    SCOPED_TRACE(r.label() + " S = " + std::to_string(r.nominal_area) + " level " + std::to_string(l));
    EXPECT_LE(lw.area_expectation, lw.bound);  // L_shape <= L (the caller checks it)
    if (l < n) EXPECT_NEAR(lw.mean, lw.expectation, tolerance(lw, positions));
    else EXPECT_LE(lw.mean, lw.expectation + tolerance(lw, positions));
    EXPECT_LE(lw.mean, lw.bound) << "se " << lw.mean_se;
    EXPECT_LE(lw.exact_mean, lw.mean);  // the ideal test never counts more (per position)
  }
}

TEST(ArchitectureWindows, AxisAlignedMeanWithinEq2) {
  // Axis-aligned rectangles up to 10:1: L_shape <= 1.39 < 1.514; no grid term.
  const int positions = 256;
  for (double aspect : {1.0, 5.0, 10.0})
    for (double area : {1.0, 10.0, 100.0}) {
      const TestRect r = make_test_rect(9, area, aspect, 0);
      ASSERT_LE(r.shape_factor(kSampleAperture, kSampleAperture), 1.4);
      for (int l = 1; l <= 9; ++l) EXPECT_EQ(rect_grid_excess(r, l), 0.0);
      expect_within_eq2(measure_windows(r, positions, 7), positions);
    }
}

TEST(ArchitectureWindows, RotatedMeanWithinEq2) {
  // 45 degrees: the square (L_shape = 2 sqrt2 / sqrt(2 pi) = 1.128) meets eq. 2, like the
  // axis-aligned rectangles: its margin, alpha_l (1.514 - 1.128) sqrt(2 pi S)/P, exceeds the grid
  // term (2 sigma - 1)/(g P)^2 < 2/(g P) with g = 8 for S >= 1. The corner windows that the edge
  // tests alone let through (2 alpha_l^2 in E: two windows at the coarse levels) are gone.
  const int positions = 256;
  for (double area : {1.0, 10.0, 100.0}) {
    const TestRect r = make_test_rect(9, area, 1.0, 45);
    ASSERT_LE(r.shape_factor(kSampleAperture, kSampleAperture), 1.2);
    const WindowTable t = measure_windows(r, positions, 11);
    expect_within_eq2(t, positions);
    EXPECT_LT(t.level[1].mean, 1.5);  // one window and a fraction, not two
  }
}

TEST(ArchitectureWindows, GridTermOfTheClosedBoxEdges) {
  // The grid term, derived in arch_analysis.hpp (rect_grid_excess), by hand at level n - 1 (P = 2
  // pixels): n = 9, g = 8 grid units a pixel, sigma = (4 P - 1) g/4 = 14 grid units, so
  // (2 sigma - 1)/(g P)^2 = 27/256 = 0.105 windows; n = 10: the samples lie half-way between grid
  // units, no term (had the samples been on the grid: sigma = 7, g = 4, 13/64 = 0.2 windows). The
  // measurement must see the term at n = 9 and not at n = 10. A 10:1 rectangle at S = 100 counts 47
  // or 48 windows there: sd ~0.5, so 2048 (1024) positions give a tolerance (4 se) below half the term.
  const TestRect r9 = make_test_rect(9, 100, 10.0, 45), r10 = make_test_rect(10, 100, 10.0, 45);
  EXPECT_DOUBLE_EQ(rect_grid_excess(r9, 8), 27.0 / 256.0);
  EXPECT_EQ(rect_grid_excess(r10, 9), 0.0);
  const int p9 = 2048, p10 = 1024;
  const WindowTable t9 = measure_windows(r9, p9, 17), t10 = measure_windows(r10, p10, 17);
  const LevelWindows &a = t9.level[8], &b = t10.level[9];
  EXPECT_LT(tolerance(a, p9), 27.0 / 256.0 / 2);
  EXPECT_NEAR(a.mean, a.area_expectation + 27.0 / 256.0, tolerance(a, p9));
  EXPECT_LT(tolerance(b, p10), 13.0 / 64.0 / 2);
  EXPECT_NEAR(b.mean, b.area_expectation, tolerance(b, p10));
}

TEST(ArchitectureWindows, ShapeFactorAboveLExceedsEq2) {
  // A 10:1 rectangle at 45 degrees has L_shape = 11/sqrt(10 pi) = 1.96 > 1.514: by the derivation
  // above E_area exceeds eq. 2 by alpha_l (W + H - L sqrt(2 pi S))/P at every level, more at the
  // finer ones, and the measured mean follows E_cons >= E_area, so the excess is the shape's, not
  // the test's. Levels where that excess is above the tolerance must show it.
  const int positions = 256;
  const TestRect r = make_test_rect(9, 100, 10.0, 45);
  ASSERT_GT(r.shape_factor(kSampleAperture, kSampleAperture), 1.9);
  const WindowTable t = measure_windows(r, positions, 13);
  int exceeding = 0;
  for (int l = 1; l < 9; ++l) {
    const LevelWindows& lw = t.level[std::size_t(l)];
    SCOPED_TRACE("level " + std::to_string(l));
    EXPECT_GT(lw.area_expectation, lw.bound);
    EXPECT_NEAR(lw.mean, lw.expectation, tolerance(lw, positions));
    if (lw.area_expectation - lw.bound > tolerance(lw, positions)) {
      EXPECT_GT(lw.mean, lw.bound);
      ++exceeding;
    }
  }
  EXPECT_GE(exceeding, 4);  // the finer half of the levels at least
}

// The setup's bounding-box edges, the premise of the above: none on an axis-aligned rectangle (its
// own edges lie on the box), one per side on a turned one; and, by hand, the window it removes.
// A diamond on the 16 x 16 raster (n = 4, sample column i at grid 64 i + 31, records.hpp) with
// vertices (1560, 500), (2060, 1000), (1560, 1500), (1060, 1000): its right vertex lies between
// sample columns 31 (grid 2015) and 32 (2079), the boundary of the level-1 windows. Level-1
// window (1, 0) (sample columns 32..63, rows 0..31) meets both right edges' half-planes:
//   x + y <= 3060: its least x + y is 2079 + 31 = 2110;  x - y <= 1060: its least is 2079 - 2015 = 64,
// and the left edges face away from it, so the four edge tests pass it although it lies right of
// the vertex. The right box edge i <= floor((2 x 2060 - 62)/128) = 31 (setup.hpp: A = -1, C = 31,
// d_0 = 31) has, in child q = 1 (k = 5 sample bits), d = 31 - 2^5 = -1 < 0 and rejects it.
// Window (0, 1) fails the lower-left edge y - x <= -60 (its least y - x is 2079 - 2015 = 64) and
// (1, 1) the lower-right one (least x + y 4158 > 3060), so level 1 has one window, (0, 0), which
// holds every covered sample.
TEST(ArchitectureWindows, SetupBoundingBoxEdges) {
  EXPECT_EQ(setup_root(rect_primitive(make_test_rect(9, 100, 5, 0), 1000, 1000, 0), 9).poly.edge_count.value(), 4u);
  EXPECT_EQ(setup_root(rect_primitive(make_test_rect(9, 100, 5, 45), 1000, 1000, 0), 9).poly.edge_count.value(), 8u);

  const int n = 4;
  TestRect diamond;
  diamond.raster_log2 = n;
  const int xs[4] = {500, 1000, 500, 0}, ys[4] = {0, 500, 1000, 500};
  std::copy(xs, xs + 4, diamond.vx);
  std::copy(ys, ys + 4, diamond.vy);
  const AnalysisWindow root = setup_root(rect_primitive(diamond, 1060, 500, 0), n);
  ASSERT_EQ(root.poly.edge_count.value(), 8u);
  int right = -1;  // the slot of the right box edge, A = -1, B = 0
  for (int e = 4; e < 8; ++e)
    if (root.poly.a[e].value() == -1 && root.poly.b[e].value() == 0) right = e;
  ASSERT_GE(right, 0);
  EXPECT_EQ(root.d[right].value(), 31);
  hls::QuadChild<AnalysisArith> child;
  hls::evaluate_child(root, 1, n, false, child);
  EXPECT_FALSE(child.covered);
  for (int e = 0; e < 4; ++e) EXPECT_GE(child.window.d[e].value(), 0) << "polygon edge " << e;
  EXPECT_EQ(child.window.d[right].value(), -1);
  PolygonWindows pw;
  count_windows(root, n, pw);
  EXPECT_EQ(pw.conservative[1], 1);
  EXPECT_EQ(pw.exact[1], 1);
}

// The depth-first walk and the cycle model count the same windows, level by level.
TEST(ArchitectureWindows, WalkEqualsTheCycleModelsLevelStats) {
  const int n = 6;
  const TestRect r = make_test_rect(n, 30, 5, 45);
  const std::vector<AnalysisWindow> roots = rect_stream(r, 24, 3);
  std::vector<long long> walked(std::size_t(n) + 1, 0);
  PolygonWindows pw;
  for (const AnalysisWindow& root : roots) {
    count_windows(root, n, pw);
    for (int l = 0; l <= n; ++l) walked[std::size_t(l)] += pw.conservative[std::size_t(l)];
  }
  for (const char* text : {"ns", "np", "nt", "4p2t", "3s3p"}) {
    const ArchMeasurement m = run_architecture(Architecture::parse(text, n), roots);
    EXPECT_EQ(m.covered, walked) << text;
  }
}

// ---- the cycle model, by hand -----------------------------------------------------------------

// A square on the formatter grid of a 16 x 16 raster (n = 4): 256 grid units a pixel, sample
// column i of the lattice at grid 64 i + 31 (records.hpp: half units s i + o, s = 128, o = 62).
// Its four edges lie on the four sides of its bounding box, so the setup adds no bounding-box edge
// (setup.hpp adds one only on a side that carries no edge of the polygon): four edge slots, the
// windows below follow from the square's edges alone, and so do the clocks derived from them. The
// tests check edge_count = 4, the premise of the derivations.
hls::FormattedPrimitive square(int x0, int y0, int x1, int y1, std::uint16_t id) {
  TestRect r;
  r.raster_log2 = 4;
  const int xs[4] = {0, x1 - x0, x1 - x0, 0}, ys[4] = {0, 0, y1 - y0, y1 - y0};
  std::copy(xs, xs + 4, r.vx);
  std::copy(ys, ys + 4, r.vy);
  return rect_primitive(r, x0, y0, id);
}

struct Timed {
  ArchStats stats;
  int pes = 0;
};

class NullSink final : public PixelSink<AnalysisArith> {
 public:
  std::uint64_t pixel(int, const QuadItem<AnalysisArith>& it, bool& full) override {
    full = false;
    return it.samples.value();
  }
};

Timed run(const char* arch, const std::vector<AnalysisWindow>& roots, int n) {
  ArchConfig cfg;
  cfg.masks = false;
  ArchModel<AnalysisArith> model(Architecture::parse(arch, n), cfg);
  auto masks = std::make_unique<hls::MaskMemory>();
  hls::mask_clear(*masks, n);
  NullSink sink;
  Timed t;
  t.stats = model.run(roots, *masks, sink);
  t.pes = model.pe_count();
  return t;
}

// Case 1: x, y in [1280, 1480] x [2304, 2504] holds samples 1311, 1375, 1439 (i = 20..22: columns
// 0..2 of pixel 5; 1247 and 1503 are outside) and rows 2335, 2399, 2463 (j = 36..38: rows 0..2 of
// pixel row 9): one window at every level,
// on the path q = 2 (level-1 window (0, 1)), 1 ((1, 2)), 0 ((2, 4)), 3 (pixel (5, 9)).
// The pipeline 4p (FIFO visible one clock after the push; an idle PE spends one clock loading):
//   t = 0 the root enters PE0's FIFO; t = 1 PE0 loads it; t = 2..5 it tests q = 0..3, emits q = 2
//   at t = 4; PE1 loads at 5, tests 6..9, emits q = 1 at 7; PE2 loads at 8, tests 9..12, emits
//   q = 0 at 9; PE3 loads at 10, tests 11..14, emits pixel q = 3 at 14; the pixel processor takes
//   it at 15: 16 clocks.
// The stack 4s loads each next window from its LIFO in the clock its last child is tested:
//   t = 1 load, 16 tests at t = 2..17, the pixel (the last child tested) taken at 18: 19 clocks.
TEST(ArchitectureCycles, OneSquareByHand) {
  const int n = 4;
  const hls::FormattedPrimitive f = square(1280, 2304, 1480, 2504, 0);
  const AnalysisWindow root = setup_root(f, n);
  EXPECT_EQ(root.poly.edge_count.value(), 4u);
  PolygonWindows pw;
  count_windows(root, n, pw);
  EXPECT_EQ(pw.conservative, (std::vector<int>{1, 1, 1, 1, 1}));
  EXPECT_EQ(pw.exact, (std::vector<int>{1, 1, 1, 1, 1}));

  const Timed p = run("4p", {root}, n);
  EXPECT_EQ(p.stats.cycles, 16);
  EXPECT_EQ(p.stats.pe_busy_cycles, (std::vector<long long>{4, 4, 4, 4}));
  EXPECT_EQ(p.stats.pe_stall_cycles, (std::vector<long long>{0, 0, 0, 0}));
  EXPECT_EQ(p.stats.pixel_records, 1);
  const Timed s = run("4s", {root}, n);
  EXPECT_EQ(s.stats.cycles, 19);
  EXPECT_EQ(s.stats.pe_busy_cycles, (std::vector<long long>{16}));
}

// Case 2: [2000, 2100]^2 holds one sample in each of pixels (7, 7), (8, 7), (7, 8), (8, 8)
// (sample 2015 is column 3 of pixel 7, 2079 column 0 of pixel 8): windows 1, 4, 4, 4, 4.
// 4p: PE0 (loads at 1) tests at 2..5 and emits A, B, C, D (q = 0..3). PE1 loads A at 3 (pushed at
// 2); B enters at 3 (start count 1: PE1 popped A), C at 4 (count 1 < 2); D at 5 finds 2 and stalls
// at 5, 6 and 7 (at 7 PE1 pops B, but ready is a register), entering at 8: PE0 busy 4, stalls 3.
// PE1 works without a gap: A's children at 4..7, emits q = 3 at 7; B 8..11 (q = 2 at 10); C
// 12..15 (q = 1 at 13); D 16..19 (q = 0 at 16). PE2: loads at 8 (idle), A' 9..12 (emits q = 3 at
// 12), B' 13..16 (q = 2 at 15), C' 17..20 (q = 1 at 18), D' 21..24 (q = 0 at 21). PE3: loads at 13,
// A'' 14..17 (pixel (7, 7), q = 3, at 17), B'' 18..21 (20), C'' 22..25 (23), D'' 26..29 (26).
// Pixels taken at 18, 21, 24, 27; the last test at 29: 30 clocks.
// 4s: 13 windows x 4 tests back to back at 2..53; the last pixel, (7, 7), is tested last (A's
// subtree comes off the LIFO last, q = 3): taken at 54, 55 clocks.
TEST(ArchitectureCycles, FourPixelSquareByHand) {
  const int n = 4;
  const AnalysisWindow root = setup_root(square(2000, 2000, 2100, 2100, 0), n);
  EXPECT_EQ(root.poly.edge_count.value(), 4u);
  PolygonWindows pw;
  count_windows(root, n, pw);
  EXPECT_EQ(pw.conservative, (std::vector<int>{1, 4, 4, 4, 4}));

  const Timed p = run("4p", {root}, n);
  EXPECT_EQ(p.stats.cycles, 30);
  EXPECT_EQ(p.stats.pe_busy_cycles, (std::vector<long long>{4, 16, 16, 16}));
  EXPECT_EQ(p.stats.pe_stall_cycles, (std::vector<long long>{3, 0, 0, 0}));
  EXPECT_EQ(p.stats.pixel_records, 4);
  const Timed s = run("4s", {root}, n);
  EXPECT_EQ(s.stats.cycles, 55);
  EXPECT_EQ(s.stats.pe_busy_cycles, (std::vector<long long>{52}));
}

// K copies of case 1: the pipeline takes a polygon every 4 clocks once full (every stage gets one
// window per polygon and loads the next in the clock it finishes one): 16 + 4 (K - 1) clocks,
// P = P_max = 1/4; the stack 16 tests a polygon back to back: 16 K + 3. eq. 5-8 predict the
// slopes: 4 and 16 clocks per polygon.
TEST(ArchitectureCycles, SteadyStateEqualsEq5To8) {
  const int n = 4;
  const AnalysisWindow root = setup_root(square(1280, 2304, 1480, 2504, 0), n);
  const std::vector<double> w{1, 1, 1, 1, 1};
  for (int k : {1, 2, 7}) {
    const std::vector<AnalysisWindow> roots(std::size_t(k), root);
    EXPECT_EQ(run("4p", roots, n).stats.cycles, 16 + 4 * (k - 1)) << k;
    EXPECT_EQ(run("4s", roots, n).stats.cycles, 16 * k + 3) << k;
  }
  EXPECT_EQ(analytic_cycles_per_polygon(Architecture::parse("4p", n), w), 4.0);
  EXPECT_EQ(analytic_cycles_per_polygon(Architecture::parse("4s", n), w), 16.0);
  EXPECT_EQ(analytic_cycles_per_polygon(Architecture::parse("2s2p", n), w), 8.0);
  EXPECT_EQ(analytic_cycles_per_polygon(Architecture::parse("4t", n), w), 4.0);
  // With t_p = t_e (the seed's k_p/k_e = 1): t_i = 4 w_(i-1) + w_i = 5, P_max = 1/5.
  EXPECT_EQ(analytic_cycles_per_polygon(Architecture::parse("4p", n), w, 1.0), 5.0);
}

TEST(ArchitectureCycles, StackIsNeverFasterThanThePipeline) {
  const int n = 6;
  for (double area : {2.0, 40.0}) {
    const std::vector<AnalysisWindow> roots = rect_stream(make_test_rect(n, area, 5, 45), 32, 5);
    const ArchMeasurement stack = run_architecture(Architecture::parse("ns", n), roots);
    // A stack tests every window on one PE: its clocks are at least its tests.
    long long tests = 0;
    for (int l = 0; l < n; ++l) tests += 4 * stack.covered[std::size_t(l)];
    EXPECT_EQ(stack.busy_cycles, tests);
    EXPECT_GE(stack.cycles, tests);
    for (const char* text : {"np", "nt", "4p2t", "5s1p", "2s2s2t"}) {
      const ArchMeasurement m = run_architecture(Architecture::parse(text, n), roots);
      EXPECT_GE(stack.cycles, m.cycles) << text << " S = " << area;
      EXPECT_EQ(m.busy_cycles, tests) << text;  // the same work, spread over PEs
    }
  }
}

// ---- masks remove work, never a visible sample ------------------------------------------------

// The pixel processor's visibility: polygons arrive front to back, a sample belongs to the first
// polygon that covers it (hls/quadtree/pixel_processor.hpp's rule, without the colours).
class OwnerSink final : public PixelSink<AnalysisArith> {
 public:
  explicit OwnerSink(int n) : side_(1 << n), owner_(std::size_t(side_) * side_ * 16, -1) {}
  std::uint64_t pixel(int, const QuadItem<AnalysisArith>& it, bool& full) override {
    const std::size_t pix = std::size_t(it.w.y.value()) * std::size_t(side_) + std::size_t(it.w.x.value());
    unsigned fresh = 0, owned = 0;
    for (int s = 0; s < 16; ++s) {
      int& o = owner_[pix * 16 + std::size_t(s)];
      if (o < 0 && it.samples.bit(s)) {
        o = int(it.w.poly.id.value());
        fresh |= 1u << s;
      }
      if (o >= 0) owned |= 1u << s;
    }
    full = fresh != 0 && owned == 0xFFFFu;
    return fresh;
  }
  const std::vector<int>& owners() const { return owner_; }

 private:
  int side_;
  std::vector<int> owner_;
};

TEST(ArchitectureMasks, OnAndOffGiveTheSameImage) {
  const int n = 6;
  // A large square in front (it fills whole windows and sets their masks), then a stream of
  // rectangles behind it and around it.
  std::vector<AnalysisWindow> roots;
  roots.push_back(setup_root(rect_primitive(make_test_rect(n, 900, 1, 0), 1000, 1000, 0), n));
  const std::vector<AnalysisWindow> rest = rect_stream(make_test_rect(n, 60, 5, 45), 40, 9);
  for (std::size_t k = 0; k < rest.size(); ++k) {
    roots.push_back(rest[k]);
    roots.back().poly.id = hls::UInt<16>(k + 1);
  }
  for (const char* text : {"np", "ns", "nt", "4p2t", "3s3p"}) {
    std::vector<int> owners[2];
    long long records[2] = {0, 0};
    for (int on = 0; on < 2; ++on) {
      ArchConfig cfg;
      cfg.masks = on != 0;
      ArchModel<AnalysisArith> model(Architecture::parse(text, n), cfg);
      auto masks = std::make_unique<hls::MaskMemory>();
      hls::mask_clear(*masks, n);
      OwnerSink sink(n);
      records[on] = model.run(roots, *masks, sink).pixel_records;
      owners[on] = sink.owners();
    }
    EXPECT_EQ(owners[0], owners[1]) << text;
    EXPECT_LT(records[1], records[0]) << text << ": the masks removed no pixel record";
  }
}

}  // namespace
}  // namespace cig::quad
