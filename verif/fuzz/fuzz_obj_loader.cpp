// libFuzzer target: the OBJ model parser (cmodel/scene/obj_loader) on arbitrary text.
#include "fuzz_input.hpp"
#include "scene/obj_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return cig::fuzz::run_input(data, size, [](const std::string& text) { cig::parse_obj(text, "fuzz.obj"); });
}
