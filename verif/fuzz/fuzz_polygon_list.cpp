// libFuzzer target: the polygon-list loader (cig-polys, cmodel/frame/screen_frame). Property: what
// the writer makes of an accepted list (the text `cig polys` writes), the loader reads back to the
// same list.
#include "frame/screen_frame.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return cig::fuzz::run_input(data, size, [](const std::string& text) {
    const cig::ScreenFrame frame = cig::parse_polygon_list(text, "fuzz.polys.json");
    const std::string written = cig::polygon_list_json(frame);
    cig::ScreenFrame again;
    try {
      again = cig::parse_polygon_list(written, "written.polys.json");
    } catch (const cig::InputError& e) {
      __builtin_fprintf(stderr, "%s\n", e.what());
      cig::fuzz::broken("an accepted polygon list, written back, is rejected");
    }
    if (cig::polygon_list_json(again) != written) cig::fuzz::broken("a written polygon list reads back differently");
  });
}
