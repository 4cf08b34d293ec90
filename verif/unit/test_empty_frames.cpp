// A frame with nothing to draw (everything culled, or an empty polygon list) goes through every
// engine: each paints the background and owns no pixel, all engines paint the same bytes, and the
// quadtree's architecture model counts the one cycle the RTL takes for it (the frame-start cycle;
// verif/cosim checks the RTL itself).
#include <string>

#include <gtest/gtest.h>

#include "frame/screen_frame.hpp"
#include "registry/engine_registry.hpp"

namespace cig {
namespace {

ScreenFrame empty_frame() {
  ScreenFrame f;
  f.raster = 64;
  f.background = Rgb(0.25, 0.5, 0.75);
  f.fog.colour = Rgb(0.9, 0.1, 0.1);
  f.fog.start = 10;
  f.fog.end = 100;
  return f;
}

TEST(EmptyFrame, EveryEnginePaintsTheSameBackgroundAndOwnsNoPixel) {
  const ScreenFrame f = empty_frame();
  std::vector<std::uint8_t> first_rgb;
  for (const std::string& name : engine_names()) {
    for (bool snap : {false, true}) {
      if (snap && !engine_info(name).can.reference) continue;  // --snap is the reference's
      SCOPED_TRACE(name + (snap ? " --snap" : ""));
      EngineOptions o;
      o.snap = snap;
      const EngineRun run = make_engine(name, o)->render(f);
      ASSERT_EQ(run.out.image.width, 64);
      ASSERT_EQ(run.out.image.height, 64);
      for (std::int32_t id : run.out.ids.id) ASSERT_EQ(id, -1);
      const std::uint8_t* p0 = run.out.image.at(0, 0);
      for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
          for (int c = 0; c < 3; ++c) ASSERT_EQ(run.out.image.at(x, y)[c], p0[c]) << x << "," << y;
      // The background 0.25, 0.5, 0.75 in 8 bits, whatever the engine's rounding: within 1 LSB.
      EXPECT_NEAR(p0[0], 0.25 * 255, 1.0);
      EXPECT_NEAR(p0[1], 0.5 * 255, 1.0);
      EXPECT_NEAR(p0[2], 0.75 * 255, 1.0);
      if (first_rgb.empty()) first_rgb = run.out.image.rgb;
      EXPECT_EQ(run.out.image.rgb, first_rgb) << "engines disagree on the background";
    }
  }
}

TEST(EmptyFrame, QuadtreeArchitectureTakesTheFrameStartCycle) {
  for (const char* arch : {"6p", "6s", "3p3t"}) {
    SCOPED_TRACE(arch);
    EngineOptions o;
    o.params["arch"] = arch;
    const EngineRun run = make_engine("quadtree", o)->render(empty_frame());
    EXPECT_EQ(run.report["cycles"]["frame"].get<long long>(), 1);
  }
}

}  // namespace
}  // namespace cig
