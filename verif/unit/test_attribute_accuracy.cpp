// Intensity, depth and fog against the float reference (issue 12, deliverable 3): the segment
// processor's perspective-correct planes, the fan split of polygons whose vertex attributes are not
// planar, full-intensity white, and slivers.
//
// The bound (derived in hls/segment/README.md, "Accuracy of I, Z/fog and colour"): with vertices
// on the formatter grid (no snap displacement) and fog starting at 0, a sample differs from the
// reference's by at most
//   I:    1/2 level (eq. 1 rounds 256 Is) + 2^-4 level (rounded gradients)  -> 255 x 0.5625 / 256
//   fog:  Z relative 2^-8 (vertex e8m7) + 2^-8 (the table's 1/Z code): the factor moves by 2^-7,
//         plus 2^-9 for its 9-bit table entry                               -> 255 x 5 / 512
//   colour x I, fog mix: half a sample LSB                                  -> 2^-9
// = 0.56 + 2.49 + 0.002 = 3.05 LSB, and the 8-bit pixels (means of 16 samples, each rounded half
// up) differ by less than 3.05 + 1, so by at most 4.
#include <cmath>
#include <cstdint>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "engine/engine.hpp"
#include "engine/fan_split.hpp"
#include "frame/screen_frame.hpp"
#include "image/image_compare.hpp"
#include "registry/engine_registry.hpp"

namespace cig {
namespace {

constexpr int kBoundLsb = 4;

// Screen coordinate of formatter grid unit g (eq. 1: X = 2048 Xs + 2047 is exact there).
double on_grid(int g) { return (g - 2047) / 2048.0; }

EngineRun run(const ScreenFrame& f, const std::string& engine, std::map<std::string, std::string> params = {},
              bool fan_split = true) {
  EngineOptions o;
  o.params = std::move(params);
  o.fan_split = fan_split;
  return make_engine(engine, o)->render(f);
}

int max_abs_against_reference(const ScreenFrame& f, const std::string& engine,
                              std::map<std::string, std::string> params = {}, bool fan_split = true) {
  const EngineRun got = run(f, engine, std::move(params), fan_split);
  const EngineRun want = run(f, "float", {}, fan_split);
  const ImageError e = compare_images(got.out.image, want.out.image, got.out.ids, want.out.ids);
  return std::max({e.max_abs[0], e.max_abs[1], e.max_abs[2]});
}

ScreenPolygon quad(double x0, double y0, double x1, double y1, double z_top, double z_bottom, Rgb colour,
                   const double (&is)[4]) {
  ScreenPolygon p;
  p.colour = colour;
  p.vertices = {{x0, y1, z_bottom, is[0]}, {x1, y1, z_bottom, is[1]}, {x1, y0, z_top, is[2]}, {x0, y0, z_top, is[3]}};
  return p;
}

// A ground quad from 1 m (bottom of the screen) to 1 km (just below the horizon), fogged from 0 to
// 1 km: 1/Z is affine in screen space, Z is not. The seed's eq. 4 interpolates Z linearly.
ScreenFrame ground_quad() {
  ScreenFrame f;
  f.raster = 128;
  f.fog = {{0.5, 0.6, 0.7}, 0, 1000};
  f.background = f.fog.colour;
  f.polygons.push_back(
      quad(on_grid(256), on_grid(1792), on_grid(3840), on_grid(4095), 1000, 1, {0.2, 0.8, 0.3}, {1, 1, 0.5, 0.5}));
  return f;
}

TEST(AttributeAccuracy, GroundQuadOneMetreToOneKilometreWithinTheBound) {
  const ScreenFrame f = ground_quad();
  for (const char* e : {"segment", "segment-double", "quadtree", "quadtree-double"})
    EXPECT_LE(max_abs_against_reference(f, e), kBoundLsb) << e;
  // The seed's screen-linear Z (interp=seed) is what the planes correct: far outside the bound.
  EXPECT_GT(max_abs_against_reference(f, "segment", {{"interp", "seed"}}), 40);
}

// Shallow slivers across the whole screen with intensity ramps: the seed's I once per raster line
// at the segment ends (interp=seed) misplaces the ramp on every row but the middle one; the planes
// take I at each sample.
TEST(AttributeAccuracy, ShallowSliversWithIntensityRampsWithinTheBound) {
  ScreenFrame f;
  f.raster = 128;
  const int rows[][3] = {{1000, 1052, 1012}, {2000, 2013, 2040}, {3001, 3090, 3005}};
  for (const auto& r : rows) {
    ScreenPolygon p;
    p.colour = {0.9, 0.9, 0.9};
    p.vertices = {{on_grid(0), on_grid(r[0]), 10, 0},
                  {on_grid(4095), on_grid(r[1]), 10, 1},
                  {on_grid(2048), on_grid(r[2]), 10, 0.5}};
    f.polygons.push_back(p);
  }
  for (const char* e : {"segment", "segment-double", "quadtree", "quadtree-double"})
    EXPECT_LE(max_abs_against_reference(f, e), kBoundLsb) << e;
  EXPECT_GT(max_abs_against_reference(f, "segment", {{"interp", "seed"}}), kBoundLsb);
}

// A terrain triangle of airfield frame 8 (channel 0) that snapping makes a sliver of 1 unit^2:
// its W gradient saturated and the plane put W <= 0 (full fog, 6 LSB) at its one covered sample.
// A saturated plane is flat at the vertices' mean (hls/pixel/attribute_planes.hpp).
TEST(AttributeAccuracy, SnappedDegenerateSliverStaysInsideItsDepthRange) {
  ScreenFrame f;
  f.raster = 512;
  f.fog = {{0.5, 0.38, 0.33}, 1500, 36000};
  f.background = {0.09, 0.08, 0.21};
  ScreenPolygon p;
  p.colour = {0.2256, 0.3076, 0.1436};
  p.vertices = {{-0.7739607891735046, 0.014708870335685765, 7039.0749872173255, 0.40985701436628397},
                {-0.6779300396133138, 0.01133552410252102, 7272.526521850501, 0.4077899692174434},
                {-0.7467211384458555, 0.013651309832621014, 7460.996319545321, 0.4092975032994997}};
  f.polygons.push_back(p);
  const EngineRun want = [&] {
    EngineOptions o;
    o.snap = true;  // the same (snapped) coverage as the engines
    return make_engine("float", o)->render(f);
  }();
  for (const char* e : {"segment", "quadtree"}) {
    const EngineRun got = run(f, e);
    const ImageError err = compare_images(got.out.image, want.out.image, got.out.ids, want.out.ids);
    EXPECT_LE(std::max({err.max_abs[0], err.max_abs[1], err.max_abs[2]}), 1) << e;
  }
}

// Full intensity on a white polygon: 255 in every engine (I = 256 Is needs its ninth bit).
TEST(AttributeAccuracy, WhiteIs255) {
  ScreenFrame f;
  f.raster = 32;
  f.polygons.push_back(quad(-1, -1, 1, 1, 5, 5, {1, 1, 1}, {1, 1, 1, 1}));
  for (const char* e : {"float", "segment", "segment-double", "quadtree", "quadtree-double"}) {
    const EngineRun r = run(f, e);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(int(r.out.image.at(5, 7)[c]), 255) << e;
  }
  const EngineRun seed = run(f, "segment", {{"interp", "seed"}});
  EXPECT_EQ(int(seed.out.image.at(5, 7)[0]), 255);
}

// A quad whose four I are not coplanar: split into its fan everywhere, every engine agrees with the
// reference within the bound; one plane per polygon (the split off) is far from it.
ScreenFrame non_planar_quad() {
  ScreenFrame f;
  f.raster = 64;
  f.polygons.push_back(
      quad(on_grid(512), on_grid(512), on_grid(3584), on_grid(3584), 20, 10, {0.9, 0.7, 0.5}, {0, 1, 0, 1}));
  return f;
}

TEST(AttributeAccuracy, NonPlanarIntensitiesSplitIntoFansAgree) {
  const ScreenFrame f = non_planar_quad();
  EXPECT_FALSE(attributes_planar(f.polygons[0]));
  for (const char* e : {"segment", "segment-double", "quadtree", "quadtree-double"})
    EXPECT_LE(max_abs_against_reference(f, e), kBoundLsb) << e;
  const EngineRun r = run(f, "quadtree");
  EXPECT_EQ(r.report.at("fan_split").at("polygons_split").get<long>(), 1);
  EXPECT_EQ(r.report.at("fan_split").at("triangles_added").get<long>(), 1);
  for (std::int32_t id : r.out.ids.id) EXPECT_LE(id, 0);  // ids name the input polygon
  EXPECT_GT(max_abs_against_reference(f, "quadtree", {}, false), 30);
}

// The reference's lattice at 1 to 256 samples per pixel: a white rectangle whose right edge lies
// 0.3 of the way into pixel 10 (raster 64: 64 grid units per pixel, pixel 10 spans [639, 703))
// covers the samples whose centre 639 + (k + 1/2) 64 / side lies left of the edge, and the pixel
// is 255 times that share (an exact count, independent of the reference's code).
TEST(ReferenceLattice, SamplesPerPixelCoverTheirShareOfAPixel) {
  ScreenFrame f;
  f.raster = 64;
  const double edge = 639 + 0.3 * 64;
  f.polygons.push_back(quad(-1, -1, (edge - 2047) / 2048, 1, 5, 5, {1, 1, 1}, {1, 1, 1, 1}));
  for (int side = 1; side <= 16; side *= 2) {
    int covered = 0;
    for (int k = 0; k < side; ++k) covered += 639 + (k + 0.5) * 64 / side < edge ? 1 : 0;
    const EngineRun r = run(f, "float", {{"spp", std::to_string(side * side)}});
    EXPECT_EQ(int(r.out.image.at(10, 20)[0]), int(std::lround(255.0 * covered / side))) << side;
    EXPECT_EQ(int(r.out.image.at(9, 20)[0]), 255);
    EXPECT_EQ(r.report.at("samples_per_pixel").get<int>(), side * side);
  }
}

TEST(FanSplit, SplitsOnlyNonPlanarPolygonsAndKeepsLightPriorities) {
  ScreenFrame f = non_planar_quad();
  f.polygons.insert(f.polygons.begin(), quad(-0.5, -0.5, 0.5, 0.5, 4, 4, {1, 0, 0}, {0.2, 0.2, 0.6, 0.6}));
  ScreenPolygon pentagon;
  for (int k = 0; k < 5; ++k)
    pentagon.vertices.push_back({0.5 * std::cos(1.2566 * k), 0.5 * std::sin(1.2566 * k), 3, k == 2 ? 1.0 : 0.0});
  f.polygons.push_back(pentagon);
  ScreenLightPoint l;
  l.priority = 2;  // before the pentagon
  f.light_points = {l, l};
  f.light_points[1].priority = 3;  // after every polygon
  const FanSplit s = split_nonplanar_polygons(f);
  EXPECT_EQ(s.polygons_split, 2);
  EXPECT_EQ(s.triangles_added, 1 + 2);
  ASSERT_EQ(s.frame.polygons.size(), 1u + 2u + 3u);
  EXPECT_EQ(s.source, (std::vector<std::int32_t>{0, 1, 1, 2, 2, 2}));
  EXPECT_EQ(s.frame.light_points[0].priority, 3);
  EXPECT_EQ(s.frame.light_points[1].priority, 6);
  IdBuffer ids(3, 1);
  ids.id = {-1, 2, 5};
  map_ids_to_source(ids, s.source);
  EXPECT_EQ(ids.id, (std::vector<std::int32_t>{-1, 1, 2}));
}

}  // namespace
}  // namespace cig
