// Clipping keeps convexity and area, and shared edges clip to bit-identical vertices.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "geometry/clip.hpp"
#include "geometry/geometric_processor.hpp"
#include "scene/polygon_checks.hpp"

namespace cig {
namespace {

// A random convex planar polygon in eye space: a regular-ish polygon with jittered angles on a
// random plane, centred near the viewing pyramid so that it crosses planes often.
ClipPolygon random_convex(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> u(-1, 1);
  const glm::dvec3 centre(4 * u(rng), 4 * u(rng), 6 + 5 * u(rng));
  glm::dvec3 a = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)) + glm::dvec3(0, 0, 1e-3));
  glm::dvec3 b = glm::normalize(glm::cross(a, glm::dvec3(u(rng), u(rng), u(rng)) + glm::dvec3(1e-3, 0, 0)));
  const double radius = 2 + 6 * std::abs(u(rng));
  std::vector<double> angle(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) angle[std::size_t(k)] = 2 * M_PI * (k + 0.45 * u(rng)) / n;
  ClipPolygon p;
  for (int k = 0; k < n; ++k) {
    const double t = angle[std::size_t(k)];
    p.v[p.n++] = {centre + radius * (std::cos(t) * a + std::sin(t) * b), 0.5 + 0.5 * u(rng)};
  }
  return p;
}

double area3(const ClipPolygon& p) {
  std::vector<glm::dvec3> v;
  for (int k = 0; k < p.n; ++k) v.push_back(p.v[k].eye);
  return 0.5 * glm::length(newell_normal(v));
}

std::vector<glm::dvec3> points(const ClipPolygon& p) {
  std::vector<glm::dvec3> v;
  for (int k = 0; k < p.n; ++k) v.push_back(p.v[k].eye);
  return v;
}

TEST(Clip, SplitByAPlaneKeepsAreaAndConvexity) {
  std::mt19937_64 rng(11);
  const ViewPyramid pyramid(std::tan(0.35), 1.0);
  int split = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const ClipPolygon p = random_convex(rng, 3 + trial % 9);
    const ClipPlane& plane = pyramid.plane[trial % kClipPlanes];
    ClipPolygon in = p, out = p;
    const bool has_in = clip_polygon(in, plane);
    const bool has_out = clip_polygon(out, plane.complement());
    const double total = area3(p);
    const double parts = (has_in ? area3(in) : 0) + (has_out ? area3(out) : 0);
    ASSERT_NEAR(parts, total, 1e-9 * total) << "trial " << trial;
    if (has_in && has_out) ++split;
    for (const ClipPolygon* q : {&in, &out}) {
      if (q->n < 3) continue;
      EXPECT_LE(q->n, p.n + 1);
      // Pieces thinner than rounding are not meaningful to test for convexity.
      if (area3(*q) < 1e-9 * total) continue;
      const std::string rule = check_convex_planar(points(*q));
      EXPECT_TRUE(rule.empty() || rule.find("repeats vertex") != std::string::npos) << rule;
    }
    for (int k = 0; has_in && k < in.n; ++k) EXPECT_GE(plane.distance(in.v[k].eye), -1e-12);
  }
  EXPECT_GT(split, 1000);  // the test exercised real cuts
}

// 2D Sutherland-Hodgman against the screen square, written independently of the 3D clipper.
std::vector<glm::dvec2> clip_square_2d(std::vector<glm::dvec2> p) {
  const glm::dvec3 lines[4] = {{1, 0, 1}, {-1, 0, 1}, {0, 1, 1}, {0, -1, 1}};  // a*x + b*y + c >= 0
  for (const auto& l : lines) {
    std::vector<glm::dvec2> out;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const glm::dvec2 a = p[i], b = p[(i + 1) % p.size()];
      const double da = l.x * a.x + l.y * a.y + l.z, db = l.x * b.x + l.y * b.y + l.z;
      if (da >= 0) out.push_back(a);
      if ((da >= 0) != (db >= 0)) out.push_back(a + (da / (da - db)) * (b - a));
    }
    p = out;
    if (p.size() < 3) return {};
  }
  return p;
}

TEST(Clip, PyramidClipProjectsToTheScreenClippedPolygon) {
  std::mt19937_64 rng(5);
  const double t = std::tan(0.35);
  const ViewPyramid pyramid(t, 0.5);
  int clipped = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    ClipPolygon p = random_convex(rng, 3 + trial % 9);
    bool in_front = true;
    for (int k = 0; k < p.n; ++k) in_front = in_front && p.v[k].eye.z > 0.5;
    if (!in_front) continue;  // the 2D comparison needs the whole polygon in front of the eye
    std::vector<glm::dvec2> projected;
    for (int k = 0; k < p.n; ++k) {
      projected.emplace_back(p.v[k].eye.x / (t * p.v[k].eye.z), -p.v[k].eye.y / (t * p.v[k].eye.z));
    }
    const std::vector<glm::dvec2> expect = clip_square_2d(projected);
    const bool kept = clip_polygon(p, pyramid, 0x1f);
    const double expect_area = expect.empty() ? 0 : std::abs(signed_area_2d(expect));
    if (!kept) {
      EXPECT_LT(expect_area, 1e-12);
      continue;
    }
    std::vector<glm::dvec2> got;
    for (int k = 0; k < p.n; ++k) {
      ScreenVertex s = project(p.v[k].eye, p.v[k].intensity, t);
      EXPECT_LE(std::abs(s.xs), 1.0);
      EXPECT_LE(std::abs(s.ys), 1.0);
      got.emplace_back(s.xs, s.ys);
    }
    EXPECT_LE(p.n, kMaxScreenVertices);
    EXPECT_NEAR(std::abs(signed_area_2d(got)), expect_area, 1e-9) << "trial " << trial;
    if (expect_area > 1e-6) {
      const std::string rule = check_convex_2d(got);
      EXPECT_TRUE(rule.empty() || rule.find("repeats vertex") != std::string::npos) << rule;
    }
    if (std::abs(expect_area - std::abs(signed_area_2d(projected))) > 1e-6) ++clipped;
  }
  EXPECT_GT(clipped, 300);
}

TEST(Clip, SharedEdgeClipsToIdenticalVertices) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  const ViewPyramid pyramid(std::tan(0.35), 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    // Two triangles sharing edge (a, b), traversed in opposite directions.
    const glm::dvec3 a(8 * u(rng), 8 * u(rng), 5 + 4 * u(rng)), b(8 * u(rng), 8 * u(rng), 5 + 4 * u(rng));
    const glm::dvec3 c(8 * u(rng), 8 * u(rng), 5 + 4 * u(rng)), d(8 * u(rng), 8 * u(rng), 5 + 4 * u(rng));
    ClipPolygon p, q;
    p.v[0] = {a, 0.1};
    p.v[1] = {b, 0.9};
    p.v[2] = {c, 0.5};
    p.n = 3;
    q.v[0] = {b, 0.9};
    q.v[1] = {a, 0.1};
    q.v[2] = {d, 0.3};
    q.n = 3;
    if (!clip_polygon(p, pyramid, 0x1f) || !clip_polygon(q, pyramid, 0x1f)) continue;
    // Every clipped vertex of p that lies on segment ab must appear bit-identically in q.
    for (int i = 0; i < p.n; ++i) {
      const glm::dvec3 e = p.v[i].eye;
      const glm::dvec3 ab = b - a;
      const double s = glm::dot(e - a, ab) / glm::dot(ab, ab);
      if (glm::length(e - (a + s * ab)) > 1e-9) continue;
      bool found = false;
      for (int k = 0; k < q.n; ++k) found = found || (q.v[k].eye == e && q.v[k].intensity == p.v[i].intensity);
      EXPECT_TRUE(found) << "trial " << trial;
    }
  }
}

}  // namespace
}  // namespace cig
