// The over-96K scene (scenes/stress/overload.polys.json, written by tools/make_overload.py): more
// segments than the segment memory's 2 x 48K words, from polygons of every area code, protected
// polygons large and small, and light points. The segment engine must choose the overload
// threshold T as the largest code whose segments (with the protected polygons' and the lights',
// which are never dropped) fit each bank, drop exactly the written polygons with a code above T,
// never a protected one, store everything it keeps, and report counts equal to a brute-force
// recount.
#include <algorithm>

#include <gtest/gtest.h>

#include "registry/engine_registry.hpp"
#include "stress/stress_support.hpp"
#include "unit/test_support.hpp"

namespace cig::stress {
namespace {

const ScreenFrame& overload_frame() {
  static const ScreenFrame frame = load_polygon_list(cig::test::source_path("scenes/stress/overload.polys.json"));
  return frame;
}

TEST(OverloadScene, IsAnOverloadScene) {
  const ScreenFrame& f = overload_frame();
  const FrameCount c = count_frame(f);
  // More segments than both banks hold; the frame memory itself is not overloaded.
  EXPECT_GT(c.total_segments(), 2 * kSegmentBankWords);
  EXPECT_EQ(c.overflowed, 0);
  // Every area code 1..15 is present, protected polygons are, including small ones (whose own
  // code would be above the threshold), and light points are.
  long per_code[kAreaCodes] = {}, small_protected = 0;
  for (std::size_t i = 0; i < f.polygons.size(); ++i) {
    const PolygonCount& p = c.polygons[i];
    if (!p.valid) continue;
    ++per_code[p.code];
    if (p.code == 0 && area_code(p.twice_area) > c.threshold) ++small_protected;
  }
  for (int code = 0; code < kAreaCodes; ++code) EXPECT_GT(per_code[code], 0) << "code " << code;
  EXPECT_GT(small_protected, 0);
  EXPECT_GT(c.light_segments[0] + c.light_segments[1], 0);
  // The threshold drops something, but not everything: codes above and below it are populated.
  EXPECT_GT(c.threshold, 1);
  EXPECT_LT(c.threshold, 15);
}

TEST(OverloadScene, ThresholdDropsAndCountsMatchBruteForce) {
  const ScreenFrame& f = overload_frame();
  const FrameCount c = count_frame(f);
  // The brute force counts the frame's polygons as they are: no fan split of the scene's
  // non-planar intensities (which would add triangles the counts do not know).
  EngineOptions o;
  o.fan_split = false;
  auto engine = make_engine("segment", o);
  const EngineRun run = engine->render(f);
  const auto& rep = run.report;
  const int t = int(num(rep.at("overload").at("threshold")));

  // The largest threshold that fits, by exhaustive search over the brute-force counts.
  EXPECT_EQ(t, c.threshold);
  EXPECT_TRUE(c.fits(t));
  EXPECT_FALSE(c.fits(t + 1));

  // Every dropped polygon has a code above T, none is protected, and every written polygon above T
  // is dropped: per code, the dropped count equals the written polygons of that code above T.
  for (int code = 0; code < kAreaCodes; ++code) {
    long written = 0;
    for (std::size_t i = 0; i < f.polygons.size(); ++i)
      if (c.polygons[i].code == code)
        written += std::count(c.written_entries[i].begin(), c.written_entries[i].end(), 1);
    const long dropped = num(rep.at("overload").at("per_area_code").at(std::size_t(code)).at("polygons_dropped"));
    EXPECT_EQ(dropped, code > t ? written : 0) << "code " << code;
  }
  EXPECT_GT(num(rep.at("overload").at("polygons_dropped")), 0);

  // What is kept fits each bank: nothing is lost to a full bank.
  EXPECT_LE(num(rep.at("segments").at("stored_even")), kSegmentBankWords);
  EXPECT_LE(num(rep.at("segments").at("stored_odd")), kSegmentBankWords);
  EXPECT_EQ(num(rep.at("segments").at("dropped_memory_full")), 0);

  // Every count against the recount.
  expect_report_matches(rep, f, c);

  // The dropped polygons are exactly those above T: with them replaced by empty polygons (same
  // indices), nothing needs dropping and the image and ids are the same, bit for bit.
  ScreenFrame kept = f;
  long removed = 0;
  for (std::size_t i = 0; i < kept.polygons.size(); ++i)
    if (c.polygons[i].valid && c.polygons[i].code > t) {
      auto& v = kept.polygons[i].vertices;
      v.assign(3, v.front());
      removed += long(c.polygons[i].entries().size());  // frame-memory entries: span pieces count each
    }
  EXPECT_EQ(removed, num(rep.at("overload").at("polygons_dropped")));
  const EngineRun again = engine->render(kept);
  EXPECT_EQ(num(again.report.at("overload").at("polygons_dropped")), 0);
  EXPECT_EQ(num(again.report.at("overload").at("threshold")), 15);
  EXPECT_TRUE(again.out.image.rgb == run.out.image.rgb);
  EXPECT_TRUE(again.out.ids.id == run.out.ids.id);
  // No dropped polygon is visible.
  std::vector<char> shown(f.polygons.size(), 0);
  for (std::int32_t id : run.out.ids.id)
    if (id >= 0) shown[std::size_t(id)] = 1;
  for (std::size_t i = 0; i < f.polygons.size(); ++i)
    if (c.polygons[i].valid && c.polygons[i].code > t) {
      EXPECT_FALSE(shown[i]) << "dropped polygon " << i << " is visible";
    }
}

// The twin on the same scene (its own formatter does not snap, so its counts differ slightly from
// the fixed engine's): the same rules hold for its own report.
TEST(OverloadScene, TwinReportIsConsistent) {
  const ScreenFrame& f = overload_frame();
  const EngineRun run = make_engine("segment-double", {})->render(f);
  expect_report_self_consistent(run.report, f.raster);
  EXPECT_GT(num(run.report.at("overload").at("polygons_dropped")), 0);
  EXPECT_EQ(num(run.report.at("segments").at("dropped_memory_full")), 0);
  EXPECT_EQ(num(run.report.at("overload").at("per_area_code").at(0).at("polygons_dropped")), 0);
}

}  // namespace
}  // namespace cig::stress
