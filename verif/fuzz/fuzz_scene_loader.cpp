// libFuzzer target: the scene loader (cmodel/scene/scene_loader) and, for a scene it accepts, the
// whole pipeline on its first frame at a 32 x 32 raster: the world database, the scene manager, the
// geometric processor and every engine on every channel. Model paths resolve against the working
// directory.
#include "fuzz_input.hpp"
#include "generator/image_generator.hpp"
#include "scene/scene_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return cig::fuzz::run_input(data, size, [](const std::string& text) {
    cig::Scene scene = cig::parse_scene(text, "fuzz.json");
    scene.raster = 32;
    const cig::ImageGenerator pipeline(scene);
    std::vector<int> channels;
    for (int c = 0; c < int(scene.channels.size()); ++c) channels.push_back(c);
    for (const char* engine : {"float", "segment", "quadtree"}) {
      for (const cig::ChannelOutput& out : pipeline.render(0, channels, engine, cig::EngineOptions{}, 1))
        if (out.out.image.width != 32) cig::fuzz::broken("an engine returned an image of the wrong size");
    }
  });
}
