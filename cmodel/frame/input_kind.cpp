#include "frame/input_kind.hpp"

#include "common/json_reader.hpp"

namespace cig {

InputKind input_kind(const std::string& text, const std::string& file) {
  return input_kind_of_document(parse_json_text(text, file), file);
}

InputKind input_kind_of_document(const nlohmann::json& doc, const std::string& file) {
  const JsonNode root(doc, file, "");
  const JsonNode format = root.at("format");
  const std::string name = format.string();
  if (name == "cig-scene") return InputKind::kScene;
  if (name == "cig-polys") return InputKind::kPolygonList;
  format.fail("must be \"cig-scene\" (a scene) or \"cig-polys\" (a polygon list), is \"" + name + "\"");
}

}  // namespace cig
