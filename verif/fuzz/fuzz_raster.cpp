// libFuzzer target: `cig raster` on a small raster. A polygon list the loader accepts is drawn by
// every engine at 32 x 32 (its geometry is in screen units, so any raster shows it); each must give
// a whole image and an owner per pixel.
#include "frame/screen_frame.hpp"
#include "fuzz_input.hpp"
#include "registry/engine_registry.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return cig::fuzz::run_input(data, size, [](const std::string& text) {
    cig::ScreenFrame frame = cig::parse_polygon_list(text, "fuzz.polys.json");
    frame.raster = 32;
    for (const char* name : {"float", "segment", "quadtree"}) {
      for (bool snap : {false, true}) {
        if (snap && !cig::engine_info(name).can.reference) continue;  // --snap is the reference's
        cig::EngineOptions options;
        options.snap = snap;
        auto engine = cig::make_engine(name, options);
        engine->check_raster(frame.raster);
        const cig::EngineRun run = engine->render(frame);
        if (run.out.image.width != frame.raster || run.out.image.height != frame.raster)
          cig::fuzz::broken("an engine returned an image of the wrong size");
      }
    }
  });
}
