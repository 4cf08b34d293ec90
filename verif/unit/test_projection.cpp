// Channel views and the perspective projection put known world points where they belong.
#include <cmath>

#include <gtest/gtest.h>

#include "geometry/geometric_processor.hpp"
#include "manager/channel_view.hpp"
#include "reference/sample_lattice.hpp"

namespace cig {
namespace {

Scene one_observer(Pose pose, std::vector<Channel> channels) {
  Scene s;
  s.keyframes = {{0, pose}};
  s.channels = std::move(channels);
  s.near = 1;
  return s;
}

ScreenVertex screen_of(const Scene& s, int channel, glm::dvec3 world) {
  ChannelView v = make_channel_view(s, 0, channel);
  return project(v.to_eye(world), 0.5, v.tan_half_fov);
}

const double kT20 = std::tan(20.0 * M_PI / 180.0);

TEST(Projection, StraightAheadCornersAndDepth) {
  Scene s = one_observer({{10, 20, 30}, 0, 0, 0}, {{"c", 0, 0, 40}});
  ScreenVertex c = screen_of(s, 0, {10, 120, 30});  // 100 m north: dead ahead
  EXPECT_NEAR(c.xs, 0, 1e-12);
  EXPECT_NEAR(c.ys, 0, 1e-12);
  EXPECT_NEAR(c.zs, 100, 1e-9);
  EXPECT_DOUBLE_EQ(c.is, 0.5);
  ScreenVertex r = screen_of(s, 0, {10 + 100 * kT20, 120, 30});  // right edge of a 40 degree view
  EXPECT_NEAR(r.xs, 1, 1e-12);
  EXPECT_NEAR(r.ys, 0, 1e-12);
  ScreenVertex up = screen_of(s, 0, {10, 120, 30 + 50 * kT20});  // half-way up: Ys grows downward
  EXPECT_NEAR(up.xs, 0, 1e-12);
  EXPECT_NEAR(up.ys, -0.5, 1e-12);
}

TEST(Projection, HeadingPitchRollAndChannelOffsets) {
  // Heading 90 looks east.
  Scene east = one_observer({{0, 0, 0}, 90, 0, 0}, {{"c", 0, 0, 40}});
  ScreenVertex e = screen_of(east, 0, {200, 0, 0});
  EXPECT_NEAR(e.xs, 0, 1e-12);
  EXPECT_NEAR(e.ys, 0, 1e-12);
  EXPECT_NEAR(e.zs, 200, 1e-9);
  // A channel yawed 40 degrees right looks at bearing 40.
  Scene three = one_observer({{0, 0, 0}, 0, 0, 0}, {{"l", -40, 0, 40}, {"c", 0, 0, 40}, {"r", 40, 0, 40}});
  const double b = 40 * M_PI / 180;
  ScreenVertex rr = screen_of(three, 2, {100 * std::sin(b), 100 * std::cos(b), 0});
  EXPECT_NEAR(rr.xs, 0, 1e-12);
  EXPECT_NEAR(rr.zs, 100, 1e-9);
  // The seam between channels: bearing 20 is the right edge of the centre channel and the left
  // edge of the right channel.
  const double s20 = 20 * M_PI / 180;
  const glm::dvec3 seam(100 * std::sin(s20), 100 * std::cos(s20), 0);
  EXPECT_NEAR(screen_of(three, 1, seam).xs, 1, 1e-12);
  EXPECT_NEAR(screen_of(three, 2, seam).xs, -1, 1e-12);
  // Pitch 10 up puts a point at elevation 10 in the centre.
  Scene up = one_observer({{0, 0, 0}, 0, 10, 0}, {{"c", 0, 0, 40}});
  const double p10 = 10 * M_PI / 180;
  EXPECT_NEAR(screen_of(up, 0, {0, 100 * std::cos(p10), 100 * std::sin(p10)}).ys, 0, 1e-12);
  // Roll 90 right wing down: the body's up axis points east, so a point to the east appears
  // straight above the centre.
  Scene roll = one_observer({{0, 0, 0}, 0, 0, 90}, {{"c", 0, 0, 40}});
  ScreenVertex rv = screen_of(roll, 0, {100 * kT20 * 0.5, 100, 0});
  EXPECT_NEAR(rv.xs, 0, 1e-12);
  EXPECT_NEAR(rv.ys, -0.5, 1e-12);
}

TEST(Projection, FormatterGridAndSampleLattice) {
  // eq. 1: X = 2048 Xs + 2047, so the screen spans grid units [-1, 4095].
  EXPECT_DOUBLE_EQ(grid_x(-1), -1);
  EXPECT_DOUBLE_EQ(grid_x(1), 4095);
  EXPECT_DOUBLE_EQ(grid_x(0), 2047);
  // At N = 512 sample i sits at grid unit 2i: pixel p's samples are 8p, 8p+2, 8p+4, 8p+6.
  SampleLattice l{512};
  EXPECT_EQ(l.size(), 2048);
  EXPECT_DOUBLE_EQ(l.from_grid(0), 0);
  EXPECT_DOUBLE_EQ(l.from_grid(6), 3);
  EXPECT_DOUBLE_EQ(l.from_grid(8), 4);
  // The screen edges are half a sample outside the first and last samples, at every raster.
  for (int n : {16, 64, 512, 1024, 4096}) {
    SampleLattice s{n};
    EXPECT_DOUBLE_EQ(s.from_screen(-1), -0.5) << n;
    EXPECT_DOUBLE_EQ(s.from_screen(1), s.size() - 0.5) << n;
  }
  // Snapping: round to the nearest grid unit and clamp to 0..4095.
  EXPECT_DOUBLE_EQ(grid_x(snap_grid_coordinate(-1)), 0);
  EXPECT_DOUBLE_EQ(grid_x(snap_grid_coordinate(1)), 4095);
  EXPECT_DOUBLE_EQ(grid_x(snap_grid_coordinate(0.25 + 0.3 / 2048)), 2559);
}

// The reference's double lattice and the kernels' integer one (hls/formatter/sample_lattice.hpp)
// put every sample of every raster at the same place: sample k at half unit H_k maps back to k.
TEST(Projection, ReferenceLatticeEqualsTheFormatterLattice) {
  for (int log2 = hls::kMinRasterLog2; log2 <= hls::kMaxRasterLog2; ++log2) {
    const SampleLattice lattice{1 << log2};
    const hls::LatticeGeometry g = hls::LatticeGeometry::for_raster(log2);
    for (int k = 0; k < lattice.size(); ++k) {
      ASSERT_EQ(lattice.from_grid(0.5 * g.sample_half(k)), double(k)) << "raster " << (1 << log2) << " sample " << k;
      ASSERT_EQ(g.first_sample_at_or_after_half(g.sample_half(k)), k);
      ASSERT_EQ(g.first_sample_at_or_after_half(g.sample_half(k) + 1), k + 1);
    }
  }
}

}  // namespace
}  // namespace cig
