// The reference's coverage rule against an exact brute-force point-in-polygon count, and
// watertightness: tilings of the screen cover every sample exactly once.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "reference/coverage.hpp"
#include "reference/reference_raster.hpp"

namespace cig {
namespace {

struct P2 {
  double x, y;
};

// Exact even-odd crossing test of the sample perturbed to (x + e, y + e^2), e -> 0+, with the
// coordinates scaled to integers. This is a different algorithm from the edge-function test, with
// the same tie semantics; on exact (dyadic) inputs the two must agree on every sample.
bool brute_force_inside(const std::vector<P2>& poly, double x, double y, double scale) {
  using I = __int128;
  auto q = [&](double v) { return I(std::llround(v * scale)); };
  const I px = q(x), py = q(y);
  bool inside = false;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const P2 a = poly[k], b = poly[(k + 1) % poly.size()];
    const I ax = q(a.x), ay = q(a.y), bx = q(b.x), by = q(b.y);
    if ((ay > py) == (by > py)) continue;  // does not cross the line y + e^2
    // Sign of x_cross(y) - x, times (by - ay)'s sign; a crossing exactly at x is left of x + e.
    const I num = (ax - px) * (by - ay) + (py - ay) * (bx - ax);
    const bool right = (by > ay) ? num > 0 : num < 0;
    if (right) inside = !inside;
  }
  return inside;
}

// Convex hull (Andrew's monotone chain), collinear points dropped.
std::vector<P2> hull(std::vector<P2> p) {
  std::sort(p.begin(), p.end(), [](P2 a, P2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  p.erase(std::unique(p.begin(), p.end(), [](P2 a, P2 b) { return a.x == b.x && a.y == b.y; }), p.end());
  if (p.size() < 3) return {};
  auto cross = [](P2 o, P2 a, P2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
  std::vector<P2> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h.size() >= 3 ? h : std::vector<P2>{};
}

CoverageSetup setup(const std::vector<P2>& p) {
  double x[kMaxScreenVertices], y[kMaxScreenVertices];
  for (std::size_t k = 0; k < p.size(); ++k) {
    x[k] = p[k].x;
    y[k] = p[k].y;
  }
  return setup_coverage(x, y, int(p.size()));
}

// One polygon compared sample by sample with the brute force over its bounding box (plus a
// margin); `got` is an m x m scratch image, all zero between calls. Returns the covered samples.
long expect_equals_brute_force(const std::vector<P2>& h, int m, double scale, std::vector<char>& got, int t) {
  const CoverageSetup s = setup(h);
  long count = 0;
  for_each_covered_sample(s, m, [&](int i, int j) {
    got[std::size_t(j) * std::size_t(m) + std::size_t(i)] = 1;
    ++count;
  });
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const P2& p : h) {
    x0 = std::min(x0, p.x);
    x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y);
    y1 = std::max(y1, p.y);
  }
  long expect = 0;
  for (int j = std::max(0, int(y0) - 2); j <= std::min(m - 1, int(y1) + 2); ++j)
    for (int i = std::max(0, int(x0) - 2); i <= std::min(m - 1, int(x1) + 2); ++i) {
      const bool in = brute_force_inside(h, i, j, scale);
      expect += in;
      char& g = got[std::size_t(j) * std::size_t(m) + std::size_t(i)];
      EXPECT_EQ(bool(g), in) << "polygon " << t << " sample (" << i << ", " << j << ")";
      g = 0;
    }
  EXPECT_EQ(count, expect) << "polygon " << t;
  return count;
}

// Random convex polygons with coordinates on a dyadic grid of step 1/scale, compared sample by
// sample with the brute force.
void compare_random_polygons(int m, double scale, int polygons, unsigned seed, bool reverse) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-0.5, m - 0.5);
  // Radii log-uniform from half a sample to a third of the screen: mostly small polygons, some huge.
  std::uniform_real_distribution<double> log_r(std::log(0.5), std::log(m / 3.0));
  long total = 0;
  std::vector<char> got(std::size_t(m) * std::size_t(m), 0);  // cleared over each bounding box
  for (int t = 0; t < polygons; ++t) {
    const double cx = u(rng), cy = u(rng), rad = std::exp(log_r(rng));
    std::vector<P2> pts;
    const int n = 3 + t % 10;
    for (int k = 0; k < n; ++k) {
      // Points in a disc around the centre, on the dyadic grid; sometimes on whole samples so
      // that edges and vertices pass exactly through samples.
      const double a = 2 * M_PI * std::uniform_real_distribution<double>(0, 1)(rng);
      const double d = rad * std::sqrt(std::uniform_real_distribution<double>(0, 1)(rng));
      const double step = (t % 3 == 0) ? 1.0 : 1.0 / scale;
      pts.push_back(
          {std::round((cx + d * std::cos(a)) / step) * step, std::round((cy + d * std::sin(a)) / step) * step});
    }
    std::vector<P2> h = hull(pts);
    if (h.size() < 3 || int(h.size()) > kMaxScreenVertices) continue;
    if (reverse) std::reverse(h.begin(), h.end());
    total += expect_equals_brute_force(h, m, scale, got, t);
    if (::testing::Test::HasFailure()) return;
  }
  EXPECT_GT(total, 1000);
}

TEST(Coverage, EqualsBruteForceOnSnappedVertices) {
  // Half-sample vertex grid: the snapped formatter grid at N = 512 (2 grid units per sample).
  compare_random_polygons(2048, 2, 300, 1, false);
  compare_random_polygons(2048, 2, 300, 2, true);
}

TEST(Coverage, EqualsBruteForceOnFineDyadicVertices) {
  // 2^-12 of a sample: products stay exact in double, so the reference's arithmetic is exact too.
  compare_random_polygons(256, 4096, 1500, 3, false);
  compare_random_polygons(256, 4096, 1500, 4, true);
}

// Twice the signed area and the turn signs of a polygon, exactly (half-sample coordinates).
bool snapped_convex(const std::vector<P2>& p) {
  double area2 = 0;
  int positive = 0, negative = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const P2 a = p[k], b = p[(k + 1) % p.size()], c = p[(k + 2) % p.size()];
    area2 += a.x * b.y - b.x * a.y;
    const double turn = (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
    positive += turn > 0;
    negative += turn < 0;
  }
  return area2 != 0 && (positive == 0 || negative == 0);
}

// Convex polygons that snapping to the half-sample grid (the formatter grid at N = 512) makes
// non-convex: thin quadrilaterals whose long sides carry extra, nearly collinear vertices, and
// slivers narrower than a grid step, whose vertices can cross (bow-ties) or swap (reversed).
std::vector<std::vector<P2>> snap_to_non_convex(int m, int wanted, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<std::vector<P2>> out;
  for (int t = 0; int(out.size()) < wanted && t < 100 * wanted; ++t) {
    const double cx = 20 + (m - 40) * unit(rng), cy = 20 + (m - 40) * unit(rng);
    const double angle = 2 * M_PI * unit(rng), length = 2 + 60 * unit(rng) * unit(rng);
    const double width = 1.2 * unit(rng) * unit(rng), bulge = 0.2 * unit(rng);
    const double ux = std::cos(angle), uy = std::sin(angle);
    std::vector<P2> exact;
    const int per_side = 1 + int(unit(rng) * 6);  // vertices per long side: up to 16 in all
    for (int side = 0; side < 2; ++side)
      for (int k = 0; k <= per_side; ++k) {
        // Along the side, from one end to the other, bowed out a little (convex before snapping).
        const double f = side == 0 ? double(k) / per_side : 1 - double(k) / per_side;
        const double along = (f - 0.5) * length;
        const double across = (side == 0 ? 1 : -1) * (width / 2 + bulge * f * (1 - f));
        exact.push_back({cx + along * ux - across * uy, cy + along * uy + across * ux});
      }
    std::vector<P2> snapped;
    for (const P2& p : exact) {
      const P2 q{std::round(p.x * 2) / 2, std::round(p.y * 2) / 2};
      if (snapped.empty() || q.x != snapped.back().x || q.y != snapped.back().y) snapped.push_back(q);
    }
    while (snapped.size() > 1 && snapped.back().x == snapped.front().x && snapped.back().y == snapped.front().y)
      snapped.pop_back();
    if (snapped.size() < 4 || snapped_convex(snapped) || int(snapped.size()) > kMaxScreenVertices) continue;
    out.push_back(snapped);
  }
  return out;
}

TEST(Coverage, CrossingRuleOnSnapToNonConvexPolygons) {
  const int m = 2048;  // N = 512
  const auto polygons = snap_to_non_convex(m, 3000, 5);
  ASSERT_EQ(polygons.size(), 3000u);
  std::vector<char> got(std::size_t(m) * std::size_t(m), 0);
  long total = 0, zero_area = 0;
  for (std::size_t t = 0; t < polygons.size(); ++t) {
    std::vector<P2> p = polygons[t];
    if (t % 2) std::reverse(p.begin(), p.end());  // either winding
    total += expect_equals_brute_force(p, m, 2, got, int(t));
    double area2 = 0;
    for (std::size_t k = 0; k < p.size(); ++k)
      area2 += p[k].x * p[(k + 1) % p.size()].y - p[(k + 1) % p.size()].x * p[k].y;
    zero_area += area2 == 0;
    if (::testing::Test::HasFailure()) return;
  }
  EXPECT_GT(total, 10000);
  EXPECT_GT(zero_area, 0);  // symmetric bow-ties: zero signed area, samples covered
}

TEST(Coverage, TieRuleIncludesLeftAndTopEdges) {
  // The square [2, 6] x [2, 6] in sample coordinates has edges and corners exactly on samples.
  const CoverageSetup s = setup({{2, 2}, {6, 2}, {6, 6}, {2, 6}});
  std::vector<std::pair<int, int>> got;
  for_each_covered_sample(s, 16, [&](int i, int j) { got.emplace_back(i, j); });
  ASSERT_EQ(got.size(), 16u);
  for (auto [i, j] : got) {
    EXPECT_GE(i, 2);
    EXPECT_LT(i, 6);
    EXPECT_GE(j, 2);
    EXPECT_LT(j, 6);
  }
}

TEST(Coverage, ScreenDoorCoversHalfOfTheSamples) {
  ScreenFrame f;
  f.raster = 64;
  ScreenPolygon p;
  p.opaque = false;
  p.vertices = {{-1, -1, 10, 1}, {1, -1, 10, 1}, {1, 1, 10, 1}, {-1, 1, 10, 1}};
  f.polygons.push_back(p);
  ReferenceStats st;
  render_reference(f, st);
  EXPECT_EQ(st.samples_covered, 256u * 256u / 2);
}

// A screen tiling: a jittered (G+1) x (G+1) vertex grid whose border lies on the screen edges,
// each cell cut into triangles (random diagonal) or into a fan around a point that hugs one of
// the cell's edges (slivers). Vertices are shared exactly between neighbours.
std::vector<std::vector<P2>> tiling(int m, int g, bool snapped, bool slivers, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2), unit(0, 1);
  const double lo = -0.5, hi = m - 0.5, cell = (hi - lo) / g;
  auto snap = [&](double v) { return snapped ? std::round(v * 2) / 2 : v; };  // half-sample grid
  std::vector<P2> v(std::size_t((g + 1) * (g + 1)));
  for (int j = 0; j <= g; ++j)
    for (int i = 0; i <= g; ++i) {
      double x = lo + i * cell, y = lo + j * cell;
      if (i > 0 && i < g) x = snap(x + jitter(rng) * cell);
      if (j > 0 && j < g) y = snap(y + jitter(rng) * cell);
      v[std::size_t(j * (g + 1) + i)] = {x, y};
    }
  std::vector<std::vector<P2>> tris;
  for (int j = 0; j < g; ++j)
    for (int i = 0; i < g; ++i) {
      const P2 a = v[std::size_t(j * (g + 1) + i)], b = v[std::size_t(j * (g + 1) + i + 1)];
      const P2 c = v[std::size_t((j + 1) * (g + 1) + i + 1)], d = v[std::size_t((j + 1) * (g + 1) + i)];
      if (slivers && (i + j) % 2 == 0) {
        // Fan around a point just inside edge ab: the triangle on ab is a sliver.
        const double t = 0.2 + 0.6 * unit(rng);
        const double off = snapped ? 0.5 : 1e-3 * unit(rng) + 1e-9;
        P2 p{snap(a.x + t * (b.x - a.x)), snap(a.y + t * (b.y - a.y)) + off};
        tris.push_back({a, b, p});
        tris.push_back({b, c, p});
        tris.push_back({c, d, p});
        tris.push_back({d, a, p});
      } else if (unit(rng) < 0.5) {
        tris.push_back({a, b, c});
        tris.push_back({a, c, d});
      } else {
        tris.push_back({a, b, d});
        tris.push_back({b, c, d});
      }
    }
  return tris;
}

void expect_watertight(int m, int g, bool snapped, bool slivers, unsigned seed) {
  const auto tris = tiling(m, g, snapped, slivers, seed);
  std::vector<std::uint8_t> count(std::size_t(m) * std::size_t(m), 0);
  for (std::size_t t = 0; t < tris.size(); ++t) {
    std::vector<P2> tri = tris[t];
    if (t % 2) std::reverse(tri.begin(), tri.end());  // either winding
    for_each_covered_sample(setup(tri), m,
                            [&](int i, int j) { ++count[std::size_t(j) * std::size_t(m) + std::size_t(i)]; });
  }
  long holes = 0, doubles = 0;
  for (auto c : count) {
    holes += c == 0;
    doubles += c > 1;
  }
  EXPECT_EQ(holes, 0) << "m=" << m << " g=" << g << " snapped=" << snapped << " slivers=" << slivers;
  EXPECT_EQ(doubles, 0) << "m=" << m << " g=" << g << " snapped=" << snapped << " slivers=" << slivers;
}

TEST(Coverage, RandomTilingCoversEverySampleOnce) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    expect_watertight(2048, 16, false, false, seed);
    expect_watertight(2048, 16, true, false, seed);
    expect_watertight(256, 40, false, false, seed);
    expect_watertight(256, 40, true, false, seed);
  }
}

TEST(Coverage, RandomTilingWithSliversCoversEverySampleOnce) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    expect_watertight(2048, 16, false, true, seed);
    expect_watertight(2048, 16, true, true, seed);
    expect_watertight(256, 50, false, true, seed);
    expect_watertight(256, 50, true, true, seed);
  }
}

TEST(Coverage, ReferenceRenderOfATilingLeavesNoBackground) {
  const int n = 128, m = 4 * n;
  ScreenFrame f;
  f.raster = n;
  f.background = {1, 0, 1};
  const SampleLattice lattice{n};
  for (const auto& tri : tiling(m, 12, false, true, 9)) {
    ScreenPolygon p;
    p.colour = {0.2, 0.5, 0.3};
    for (const P2& q : tri) {
      // Back from sample coordinates to Xs, Ys (the inverse of the lattice map).
      auto back = [&](double s) {
        return ((s / (kSamplesPerSide / lattice.units_per_pixel())) - 1 + lattice.units_per_pixel() / 8 - kGridOffset) /
               kGridScale;
      };
      p.vertices.push_back({back(q.x), back(q.y), 10, 1});
    }
    f.polygons.push_back(p);
  }
  ReferenceStats st;
  RasterImage out = render_reference(f, st);
  EXPECT_EQ(st.samples_covered, std::uint64_t(m) * std::uint64_t(m));
  for (auto id : out.ids.id) ASSERT_GE(id, 0);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) ASSERT_EQ(out.image.at(x, y)[1], std::uint8_t(std::lround(0.5 * 255))) << x << "," << y;
}

}  // namespace
}  // namespace cig
