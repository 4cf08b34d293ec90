// The error attribution of `cig compare`: an engine's error against the z-buffered reference,
// split with the help of the same reference rendered with visibility by priority order.
#include <gtest/gtest.h>

#include "image/image_compare.hpp"

namespace cig {
namespace {

void set(Image& im, int x, int v) { im.at(x, 0)[0] = im.at(x, 0)[1] = im.at(x, 0)[2] = std::uint8_t(v); }

TEST(ImageCompare, PriorityAttributionSeparatesListOrderFromTheRest) {
  // Six pixels in a row; ids and grey levels per pixel of the engine, the z-buffered reference
  // and the reference with visibility by priority:
  //   0: same everywhere                          -> nothing
  //   1: engine and priority reference show polygon 2, the reference polygon 1
  //                                               -> id differs, explained by priority order
  //   2: engine shows polygon 3, both references 1 -> id differs, not explained
  //   3: same id; the priority reference shows a light (colour 200) the reference hides,
  //      the engine shows it too                  -> priority colour, error 100 per channel
  //   4: same id; the priority reference differs by 2 LSB only -> shading (not counted)
  //   5: same id and colour in both references; the engine is off by 10 -> shading
  const int engine_ids[6] = {0, 2, 3, 4, 5, 6}, ref_ids[6] = {0, 1, 1, 4, 5, 6}, prio_ids[6] = {0, 2, 1, 4, 5, 6};
  const int engine_grey[6] = {10, 50, 60, 200, 100, 110}, ref_grey[6] = {10, 40, 40, 100, 100, 100},
            prio_grey[6] = {10, 50, 40, 200, 102, 100};
  Image engine(6, 1), ref(6, 1), prio(6, 1);
  IdBuffer engine_id(6, 1), ref_id(6, 1), prio_id(6, 1);
  for (int x = 0; x < 6; ++x) {
    set(engine, x, engine_grey[x]);
    set(ref, x, ref_grey[x]);
    set(prio, x, prio_grey[x]);
    engine_id.id[std::size_t(x)] = engine_ids[x];
    ref_id.id[std::size_t(x)] = ref_ids[x];
    prio_id.id[std::size_t(x)] = prio_ids[x];
  }
  const PriorityAttribution a = attribute_priority(engine, engine_id, ref, ref_id, prio, prio_id);
  EXPECT_EQ(a.ids_priority_vs_depth, 1);
  EXPECT_EQ(a.pixels_priority_colour, 1);
  EXPECT_DOUBLE_EQ(a.sum_squared_priority_colour, 3 * 100.0 * 100.0);

  const ImageError e = compare_images(engine, ref, engine_id, ref_id);
  EXPECT_EQ(e.pixels_ids_differ, 2);
  EXPECT_DOUBLE_EQ(e.sum_squared_ids_differ, 3 * (10.0 * 10 + 20.0 * 20));
  EXPECT_DOUBLE_EQ(e.sum_squared - e.sum_squared_ids_differ - a.sum_squared_priority_colour, 3 * 10.0 * 10);

  PriorityAttribution total;
  total.add(a);
  total.add(a);
  EXPECT_EQ(total.pixels_priority_colour, 2);
  EXPECT_THROW(attribute_priority(engine, engine_id, Image(5, 1), ref_id, prio, prio_id), std::runtime_error);
}

}  // namespace
}  // namespace cig
