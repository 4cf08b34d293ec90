// The float reference splits an image into strips of rows over --threads workers: every split
// (1 to 4 workers) gives the same image, ids and sample counts, in each of its modes (z-buffer or list order,
// snapped or not, 1 to 64 samples per pixel, screen-door polygons, light points).
#include <gtest/gtest.h>

#include "frame/screen_frame.hpp"
#include "reference/reference_raster.hpp"
#include "test_support.hpp"

namespace cig {
namespace {

void expect_same_for_any_threads(const ScreenFrame& frame, Visibility visibility, bool snap, int side) {
  auto render = [&](int threads, ReferenceStats& st) {
    return snap ? render_reference_snapped(frame, st, visibility, side, threads)
                : render_reference(frame, st, visibility, side, threads);
  };
  ReferenceStats one;
  const RasterImage expect = render(1, one);
  for (int threads : {2, 3, 4}) {
    ReferenceStats st;
    const RasterImage got = render(threads, st);
    const std::string what = "threads " + std::to_string(threads) + " snap " + std::to_string(snap) + " side " +
                             std::to_string(side) + " priority " + std::to_string(visibility == Visibility::kPriority);
    EXPECT_TRUE(got.image.rgb == expect.image.rgb) << what;
    EXPECT_TRUE(got.ids.id == expect.ids.id) << what;
    EXPECT_EQ(st.samples_covered, one.samples_covered) << what;
    EXPECT_EQ(st.samples_written, one.samples_written) << what;
    EXPECT_EQ(st.light_samples, one.light_samples) << what;
  }
}

TEST(ReferenceThreads, StripsOnAnyNumberOfWorkersGiveTheSameImage) {
  // The overload list has light points; every third polygon made screen-door transparent.
  ScreenFrame frame = load_polygon_list(test::source_path("scenes/stress/overload.polys.json"));
  for (std::size_t k = 0; k < frame.polygons.size(); k += 3) frame.polygons[k].opaque = false;
  for (Visibility v : {Visibility::kDepth, Visibility::kPriority})
    for (bool snap : {false, true}) expect_same_for_any_threads(frame, v, snap, 4);
  expect_same_for_any_threads(frame, Visibility::kDepth, false, 1);
  expect_same_for_any_threads(frame, Visibility::kDepth, true, 8);
}

}  // namespace
}  // namespace cig
