// The architecture analysis of seed 004 (SPEC E), measured with the project's own kernels and
// cycle model: `cig arch` (cmodel/cli/arch_command.cpp) prints it, verif/unit/test_architecture.cpp
// checks it, docs/results/architecture.md discusses it.
//
//  * eq. 10: the PE count N_arch of the pipeline-trees (i-1)p(n-i+1)t beside Architecture::pe_count.
//  * eq. 2-3: the bound on w_i(S), the windows a polygon of area S pixels covers at level i, beside
//    w_i measured on test rectangles (the seed's typical test polygon) set up by the bit-accurate
//    setup kernel and walked with the PE kernel (hls::evaluate_child, no masks).
//  * eq. 5-9: cycles per polygon of any architecture: analytic (the seed's idealisation) and
//    measured (quad::ArchModel, clock by clock, masks off).
//
// Units. Areas in pixels; positions on the formatter grid (eq. 1 of seed 001: 4096 units a
// screen, g = 2^(12 - n) units a pixel). The aperture of the sample lattice is alpha = beta = 3/4
// pixel (hls/quadtree/records.hpp: a level-l window spans 2^(n-l) - 1/4 pixels of samples).
//
// Test rectangles. Vertices lie on the grid, so a rectangle of nominal area S and aspect r gets
// integer side vectors: axis-aligned (w, 0), (0, h), or rotated by 45 degrees (a, a), (-b, b);
// its exact area and aspect are reported beside the nominal ones. The setup (hls/quadtree/setup.hpp)
// adds a bounding-box edge on every side of the box that carries no edge of the polygon: none to an
// axis-aligned rectangle, four to a turned one (8 edge slots in all).
//
// Positions. The seed's w_i(S) is the mean over positions on the infinite lattice of window
// centres. The level-1 windows repeat every N/2 pixels and every finer level's period divides
// that, so positions drawn uniformly (on the grid) from one N/2 x N/2 square centred on the
// screen give the lattice mean at every level, with no screen border in the way (a polygon
// narrower than N/2 pixels then never reaches the screen's edge). Draws are stratified: x jittered
// in K equal strata, y the same strata in a random order.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "hls/formatter/records.hpp"
#include "hls/quadtree/records.hpp"
#include "quadtree/arch_model.hpp"
#include "quadtree/architecture.hpp"

namespace cig::quad {

using AnalysisArith = hls::DefaultQuadArith;  // coverage is exact integer work in every format
using AnalysisWindow = hls::QuadWindow<AnalysisArith>;

// ---- eq. 10 ---------------------------------------------------------------------------------
struct SeedPeRow {
  int i = 0;                // eq. 10's index: the tree has n - i + 1 levels
  std::string arch;         // the seed's label (10t, 1p9t, ..., 8p2t, 10p)
  long long formula = 0;    // eq. 10
  long long parsed = 0;     // Architecture::parse(arch, n).pe_count()
  double seed_printed = 0;  // the seed's table
  std::string seed_text;    // as printed, e.g. "8.738e4"
};
// The seed's table of N_arch for n = 10 (i = 1..10).
std::vector<SeedPeRow> seed_pe_table();
// x rounded to `digits` significant digits.
double round_significant(double x, int digits);

// ---- eq. 2-3 --------------------------------------------------------------------------------
constexpr double kSeedShapeFactor = 1.514;  // L of the seed's figures
constexpr double kSampleAperture = 0.75;    // alpha = beta of the 4 x 4 sample lattice, pixels

// eq. 3: alpha_i = 1 + 2^(i-n) (alpha - 1), the window's relative size at level i.
double seed_relative_aperture(int n, int level, double alpha);
// eq. 2: w_i(S) <= 4^(i-n) S + 2^(i-n) L sqrt((alpha_i^2 + beta_i^2) pi S) + alpha_i beta_i.
double seed_window_bound(int n, int level, double area, double alpha, double beta, double shape_factor);

// ---- test rectangles ------------------------------------------------------------------------
struct TestRect {
  int raster_log2 = 9;
  double nominal_area = 1, nominal_aspect = 1;
  int rotation_deg = 0;      // 0 or 45
  int vx[4] = {0, 0, 0, 0};  // vertices, grid units from the bounding box's min corner
  int vy[4] = {0, 0, 0, 0};
  int width = 0, height = 0;  // bounding box, grid units
  double area = 0;            // pixels, exact
  double aspect = 1;          // long side / short side, exact
  std::string label() const;  // e.g. "5:1@45"
  // The shape factor that makes eq. 2's middle term the exact mixed area of the polygon widened by
  // an alpha x beta box: (alpha H + beta W) / sqrt((alpha^2 + beta^2) pi S), W and H the extents.
  double shape_factor(double alpha, double beta) const;
};

// The grid rectangle closest to area S (pixels) and aspect r >= 1; throws InputError (naming
// `option`) when it does not fit the level-1 period (N/2 pixels).
TestRect make_test_rect(int raster_log2, double area, double aspect, int rotation_deg,
                        const std::string& option = "--areas");
// The formatted polygon with the bounding box's min corner at grid position (x, y).
hls::FormattedPrimitive rect_primitive(const TestRect& r, int x, int y, std::uint16_t id);
// Positions (bounding-box min corners) over one level-1 period (see above).
std::vector<std::pair<int, int>> period_positions(const TestRect& r, int count, std::uint32_t seed);
// Positions uniform over the whole screen (the rectangle inside it): the performance streams.
std::vector<std::pair<int, int>> screen_positions(const TestRect& r, int count, std::uint32_t seed);
// The setup kernel's level-0 window of a one-piece polygon (rectangles always are).
AnalysisWindow setup_root(const hls::FormattedPrimitive& f, int raster_log2);
// The expectation of the conservative coverage test's window count over translations (levels
// 1..n-1; the pixel level tests samples exactly and counts no more). A window passes when every
// edge's maximum over the window's sample box (a x a pixels, a = alpha_l P, P = 2^(n-l) pixels)
// is >= 0. The box's normals are x and y, and the setup gives a turned rectangle a bounding-box edge
// on each side of its box (an axis-aligned one has its own edges there), so the edge normals
// include every separating axis of the rectangle and the box: the test is the exact overlap test
// (separating-axis theorem), at any rotation, and a window passes when its position lies in the
// Minkowski sum M of the rectangle and the box.
//
// Over continuous translations (the seed's mean) the count's mean is M's area in windows: widening
// a convex polygon of extents W x H by a along x adds a H, then along y a (W + a), so
//   E_area = S/P^2 + alpha_l (W + H)/P + alpha_l^2,
// the corner term alpha_l^2 whatever the rotation. (Without the box edges a 45-degree rectangle's
// widened corners stayed square: 2 alpha_l^2.) It is eq. 2 with the rectangle's own shape factor
// (TestRect::shape_factor) for L, so E_area <= eq. 2 exactly when that factor is <= L.
double rect_overlap_area(const TestRect& r, int level);
// The analysis draws translations on the formatter grid (g = 2^(12-n) units a pixel), as the
// hardware sees polygons, so M's boundary is hit with positive probability and the mean is
// #(grid points in M) / (g P)^2, M's sides closed or open as their tests: a polygon edge that owns
// its ties (setup.hpp's tie rule) closed, the others open, the box edges closed. When the samples
// lie on the grid (half-unit offset o even: n <= 9) M is a lattice polygon and Pick's theorem gives
// #points = area - b/2 + 1 + b_in, b its boundary points, b_in those it keeps:
//  * axis-aligned: left and top sides closed, right and bottom open, one corner kept:
//    b_in = b/2 - 1, no excess;
//  * at 45 degrees M is an octagon: four closed axis sides (box edges) of sigma = (4P - 1) g/4
//    grid units, one closed diagonal of each parallel pair (lengths u, v: the side vectors (u, u),
//    (-v, v)), and the 4 ends of the closed diagonals: b_in = 4 sigma + u + v - 2 against
//    b/2 = 2 sigma + u + v, an excess of (2 sigma - 1) points: (2 sigma - 1)/(g P)^2 windows,
//    about 2/(g P) (0.11 window at level 8 of n = 9).
// At n = 10 the samples lie half-way between grid units, and so do M's axis sides: the rectangle
// they bound holds exactly its area in grid points, and M is that rectangle less four corner
// triangles, one per diagonal, whose legs m (equal for parallel diagonals) hold m(m - 1)/2 grid
// points off M behind a closed diagonal and m(m + 1)/2 behind an open one: each parallel pair
// removes m^2 points, the two triangles' area. No excess.
double rect_grid_excess(const TestRect& r, int level);
// E_area + the grid excess: the mean that measure_windows estimates (levels 1..n-1).
double rect_conservative_expectation(const TestRect& r, int level);

// ---- window counts --------------------------------------------------------------------------
// Per level 0..n: windows the PE's conservative test passes (w_l, the work of seed 004) and
// windows that really hold a covered sample (the ideal overlap test).
struct PolygonWindows {
  std::vector<int> conservative, exact;
};
// A plain depth-first walk of hls::evaluate_child from the root, no masks.
void count_windows(const AnalysisWindow& root, int raster_log2, PolygonWindows& out);

struct LevelWindows {
  double mean = 0, exact_mean = 0;  // over the positions
  double mean_se = 0;               // standard error of `mean` (i.i.d. formula; stratified draws do better)
  int max = 0, exact_max = 0;
  double bound = 0;             // eq. 2 at the rectangle's exact area, L = kSeedShapeFactor
  double area_expectation = 0;  // rect_overlap_area: continuous translations (eq. 2 with L_shape)
  double expectation = 0;       // rect_conservative_expectation: the analysis' grid translations
};
struct WindowTable {
  TestRect rect;
  int positions = 0;
  std::vector<LevelWindows> level;  // 0..n
};
WindowTable measure_windows(const TestRect& r, int positions, std::uint32_t seed);

// ---- architectures --------------------------------------------------------------------------
// The roots of a stream of `count` rectangles at screen_positions (opaque, in priority order).
std::vector<AnalysisWindow> rect_stream(const TestRect& r, int count, std::uint32_t seed);

struct ArchMeasurement {
  std::string arch;  // normalised text
  long long pes = 0;
  int polygons = 0;
  long long cycles = 0;
  double cycles_per_polygon = 0;
  double utilisation = 0;  // busy PE cycles / (cycles x PEs)
  long long busy_cycles = 0, stall_cycles = 0;
  std::vector<long long> covered;  // per level 0..n: windows emitted (w_l summed over the stream)
  double seconds = 0;              // host run time
};
// Runs the stream through ArchModel (masks off, `fifo_depth`), pixels into a sink that drops them.
ArchMeasurement run_architecture(const Architecture& arch, const std::vector<AnalysisWindow>& roots,
                                 int fifo_depth = 2);

// eq. 5-8 in units of t_e: t_l = 4 w_(l-1) + (t_p/t_e) w_l; a stack stage takes the sum of its
// levels' t_l, a pipeline stage its t_l, a tree its first level's t_l (its root PE: the seed's
// P_nt >= 1/t_1); the architecture runs at its slowest stage (the seed's ranking, eq. 8). `w` holds
// the mean windows per level 0..n (w_0 = 1). This project's PE (arch_model.hpp) has t_e = 1 clock
// and t_p = 0: the result is then clocks per polygon.
double analytic_cycles_per_polygon(const Architecture& arch, const std::vector<double>& w, double tp_over_te = 0);
// P_max = 1 / (4 t_e + t_p) (eq. 5 with one window per level): 1/4 polygon per clock here.
constexpr double kSeedMaxPolygonsPerClock = 0.25;
// The seed's own model of Fig. 4: w_0 = 1 and w_1..w_n from eq. 2 (L, alpha = beta).
std::vector<double> seed_model_windows(int n, double area, double alpha, double shape_factor);
// The parameters of the seed's Fig. 4: alpha = 2, L = 1.514, k_p/k_e = t_p/t_e = 1.
constexpr double kSeedFig4Aperture = 2.0;
constexpr double kSeedFig4TpOverTe = 1.0;

}  // namespace cig::quad
