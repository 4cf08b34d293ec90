// Light points in the float reference: under kDepth a light is visible or hidden as a whole by the
// surface depth at its exact centre; under kPriority it takes part in the list order per sample,
// as the engines' light point units do.
#include <gtest/gtest.h>

#include <cmath>

#include "reference/reference_raster.hpp"
#include "reference/sample_lattice.hpp"

namespace cig {
namespace {

constexpr int kRaster = 512;

// A ground polygon filling the screen, seen at a grazing angle: far (Zs = 1000) at the top of the
// screen and near (Zs = 10) at the bottom, so its w = 1/Zs grows by about 4.8e-5 per sample row.
ScreenPolygon ground() {
  ScreenPolygon p;
  p.vertices = {{-1, -1, 1000, 1}, {1, -1, 1000, 1}, {1, 1, 10, 1}, {-1, 1, 10, 1}};
  p.colour = {0.2, 0.2, 0.2};
  return p;
}

// w of ground() at screen row ys (affine in ys, between the top and bottom rows).
double ground_w(double ys) { return 1.0 / 1000 + (ys + 1) / 2 * (1.0 / 10 - 1.0 / 1000); }

// Screen Ys whose sample coordinate is `row` (the lattice is affine in Ys).
double ys_of_sample_row(double row) {
  const SampleLattice lattice{kRaster};
  const double a = lattice.from_screen(1) - lattice.from_screen(0), b = lattice.from_screen(0);
  return (row - b) / a;
}

ScreenLightPoint red_light(double xs, double ys, double zs, std::int32_t priority) {
  ScreenLightPoint l;
  l.xs = xs;
  l.ys = ys;
  l.zs = zs;
  l.ds = 7.0 / kGridScale;  // the largest disc, D = 7 grid units: about 10 samples
  l.colour = {1, 0, 0};
  l.priority = priority;
  return l;
}

int red_at(const RasterImage& r, double xs, double ys) {
  const int px = int((grid_x(xs) + 1) / 8), py = int((grid_x(ys) + 1) / 8);  // pixel p spans [8p - 1, 8p + 7)
  return r.image.at(px, py)[0];
}

TEST(ReferenceLights, GroundLightAtGrazingAngleIsTestedAtItsCentreNotTheNearestSample) {
  // A light just in front of the ground at its own position (a runway light 0.3 m above it, seen
  // from afar) is drawn, one just behind it is hidden as a whole, wherever the centre falls
  // between two sample rows: at 1000.6 the nearest sample (row 1001) shows nearer ground than the
  // light, at 1000.4 the nearest sample (row 1000) shows farther ground, so a test at the nearest
  // sample would hide the first light or show the second.
  for (double row : {1000.6, 1000.4}) {
    const double ys = ys_of_sample_row(row), xs = 0.1;
    const double w_nearest = ground_w(ys_of_sample_row(std::round(row)));
    ScreenFrame f;
    f.raster = kRaster;
    f.polygons = {ground()};
    for (bool in_front : {true, false}) {
      const double w_light = ground_w(ys) * (in_front ? 1 + 1e-5 : 1 - 1e-5);
      if (in_front == (row > 1000.5)) {  // the two cases the nearest sample gets wrong
        ASSERT_EQ(w_light < w_nearest, in_front) << "row " << row << ": the nearest sample would decide otherwise";
      }
      f.light_points = {red_light(xs, ys, 1.0 / w_light, 1)};
      ReferenceStats stats;
      const RasterImage r = render_reference(f, stats, Visibility::kDepth);
      if (in_front) {
        EXPECT_GT(stats.light_samples, 0u) << "row " << row;
        EXPECT_GT(red_at(r, xs, ys), 51 + 20) << "row " << row << ": the light is drawn over the ground (red 51)";
      } else {
        EXPECT_EQ(stats.light_samples, 0u) << "row " << row;
        EXPECT_EQ(red_at(r, xs, ys), 51) << "row " << row;
      }
    }
  }
}

TEST(ReferenceLights, PriorityVisibilityFollowsTheListAsTheEnginesDo) {
  // A near light (Zs = 5, nearer than all ground) listed after the ground polygon: the z-buffer
  // shows it, visibility by list order hides it; listed before the ground, both show it.
  const double xs = -0.2, ys = 0.05;
  ScreenFrame f;
  f.raster = kRaster;
  f.polygons = {ground()};
  for (std::int32_t priority : {0, 1}) {
    f.light_points = {red_light(xs, ys, 5, priority)};
    ReferenceStats sd, sp;
    const RasterImage depth = render_reference(f, sd, Visibility::kDepth);
    const RasterImage prio = render_reference(f, sp, Visibility::kPriority);
    EXPECT_GT(red_at(depth, xs, ys), 51 + 20) << "priority " << priority;
    if (priority == 0) EXPECT_GT(red_at(prio, xs, ys), 51 + 20);
    else EXPECT_EQ(red_at(prio, xs, ys), 51);
  }

  // Two lights on the same samples: under kPriority the one earlier in the list wins, whatever
  // their depths (the far green light listed first hides the near red one).
  ScreenLightPoint green = red_light(xs, ys, 50, 0);
  green.colour = {0, 1, 0};
  f.light_points = {red_light(xs, ys, 5, 0), green};
  f.light_points[0].priority = 1;
  f.light_points[1].priority = 0;
  f.polygons.clear();
  ReferenceStats s;
  const RasterImage r = render_reference(f, s, Visibility::kPriority);
  const int px = int((grid_x(xs) + 1) / 8), py = int((grid_x(ys) + 1) / 8);
  EXPECT_EQ(r.image.at(px, py)[0], 0);
  EXPECT_GT(r.image.at(px, py)[1], 20);
  const RasterImage d = render_reference(f, s, Visibility::kDepth);
  EXPECT_GT(d.image.at(px, py)[0], 20) << "by depth the near red light wins";
}

}  // namespace
}  // namespace cig
