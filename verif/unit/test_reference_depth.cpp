// Depth in the float reference: coplanar decals keep their list priority under the z-buffer, and
// the snapped reference's depth stays within the polygon's vertex depths (no extrapolation to the
// samples that snapping adds).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "reference/reference_raster.hpp"

namespace cig {
namespace {

constexpr int kRaster = 256;

std::int32_t id_at(const RasterImage& r, int x, int y) {
  return r.ids.id[std::size_t(y) * std::size_t(kRaster) + std::size_t(x)];
}

// Pixel x (or y) -> screen Xs (Ys) of its centre: pixel p spans [u p - 1, u p - 1 + u) grid units,
// X = 2048 Xs + 2047 (README conventions).
double screen_of_pixel(double p) {
  const double u = 4096.0 / kRaster;
  return (u * p - 1 + u / 2 - 2047) / 2048;
}

// A polygon on the screen plane w = w0 + a Xs + b Ys (w = 1/Zs): Zs at each vertex from the plane.
ScreenPolygon on_plane(const std::vector<std::pair<double, double>>& pixels, double w0, double a, double b, Rgb c) {
  ScreenPolygon p;
  for (auto [px, py] : pixels) {
    const double xs = screen_of_pixel(px), ys = screen_of_pixel(py);
    p.vertices.push_back({xs, ys, 1.0 / (w0 + a * xs + b * ys), 1});
  }
  p.colour = c;
  return p;
}

// Decals (green) before the surface they lie on (blue), both on one plane, under the z-buffer: no
// pixel inside a decal shows the surface. Random planes, from facing the eye to grazing.
TEST(ReferenceDepth, CoplanarDecalsKeepTheirListPriority) {
  std::mt19937_64 rng(0xDECA1);
  auto unit = [&] { return double(rng() >> 11) * 0x1.0p-53; };
  long inside = 0, surface_shown = 0;
  for (int t = 0; t < 40; ++t) {
    // w from 1/20 to 1/5000 over the screen: a tilted ground, a wall, or nearly facing.
    const double w_top = 1.0 / (20 + 4980 * unit()), w_bottom = 1.0 / (2 + 30 * unit());
    const double a = (unit() - 0.5) * 0.5 * (w_bottom - w_top), b = (w_bottom - w_top) / 2;
    const double w0 = (w_top + w_bottom) / 2;
    ScreenFrame f;
    f.raster = kRaster;
    for (int d = 0; d < 6; ++d) {
      const double x0 = 10 + 200 * unit(), y0 = 10 + 200 * unit(), w = 8 + 30 * unit(), h = 2 + 20 * unit();
      f.polygons.push_back(
          on_plane({{x0, y0}, {x0 + w, y0 + 0.3 * h}, {x0 + w, y0 + h}, {x0, y0 + 0.7 * h}}, w0, a, b, {0, 1, 0}));
    }
    f.polygons.push_back(on_plane({{0, 0}, {256, 0}, {256, 256}, {0, 256}}, w0, a, b, {0, 0, 1}));
    ReferenceStats st;
    const RasterImage out = render_reference(f, st, Visibility::kDepth);
    for (int y = 0; y < kRaster; ++y)
      for (int x = 0; x < kRaster; ++x) {
        // A pixel whose id is a decal and whose neighbours are that decal too lies inside it.
        const std::int32_t id = id_at(out, x, y);
        if (id < 0 || id >= 6 || x == 0 || y == 0 || x + 1 == kRaster || y + 1 == kRaster) continue;
        if (id_at(out, x - 1, y) != id || id_at(out, x + 1, y) != id || id_at(out, x, y - 1) != id ||
            id_at(out, x, y + 1) != id)
          continue;
        ++inside;
        surface_shown += out.image.at(x, y)[2] > 0;
      }
  }
  EXPECT_GT(inside, 10000);
  EXPECT_EQ(surface_shown, 0);
}

// Slivers a third of a pixel tall, far (Z = 1000) along their top edge and nearer (500) along
// their bottom edge. The top edge lies a quarter grid unit below a sample row (pixel coordinate
// q sits at grid unit 16 q + 7 at N = 256, sample rows at 16 p + 1, 5, 9, 13), so snapping (to the
// nearest grid unit) lifts it onto the row: the snapped reference covers that row, outside the
// exact sliver, where the exact 1/Z plane extrapolates beyond the farthest vertex (Z about 1,050).
// With fog starting just beyond the farthest vertex, nothing may fog.
TEST(ReferenceDepth, SnappedDepthStaysWithinTheVertexDepths) {
  ScreenFrame f;
  f.raster = kRaster;
  f.fog.colour = {1, 0, 0};
  f.fog.start = 1000.5;
  f.fog.end = 1000.6;
  long covered = 0;
  for (int k = 0; k < 60; ++k) {
    const double y = 4 + 4 * (k / 2) + (k % 2 ? 0.25 : 0) + (2.0 + 0.25 + 0.05 * (k % 3)) / 16;  // row 16p+9 or +13
    const double x0 = 3 + 0.37 * k, x1 = 240 - 0.29 * k;
    ScreenPolygon p;
    p.vertices = {{screen_of_pixel(x0), screen_of_pixel(y), 1000, 1},
                  {screen_of_pixel(x1), screen_of_pixel(y), 1000, 1},
                  {screen_of_pixel(x1), screen_of_pixel(y + 0.3), 500, 1},
                  {screen_of_pixel(x0), screen_of_pixel(y + 0.3 + 0.01 * (k % 3)), 500, 1}};
    p.colour = {0, 1, 0};
    f.polygons.push_back(p);
  }
  ReferenceStats st;
  const RasterImage out = render_reference_snapped(f, st, Visibility::kDepth);
  long fogged = 0;
  for (int y = 0; y < kRaster; ++y)
    for (int x = 0; x < kRaster; ++x) {
      covered += out.image.at(x, y)[1] > 0;
      fogged += out.image.at(x, y)[0] > 0;
    }
  EXPECT_GT(covered, 1000);
  EXPECT_EQ(fogged, 0);
}

}  // namespace
}  // namespace cig
