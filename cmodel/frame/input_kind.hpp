// The two input formats of the commands that take either (compare, sweep, cosim): a scene
// ("cig-scene") or a polygon list ("cig-polys"), told apart by the document's top-level "format"
// field, never by searching the text (a scene may well name a channel "cig-polys").
#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

namespace cig {

enum class InputKind { kScene, kPolygonList };

// Parses `text` (the contents of `file`); InputError when it is not JSON, not an object, or its
// "format" is neither.
InputKind input_kind(const std::string& text, const std::string& file);
// The same of a parsed document (parse_json_text).
InputKind input_kind_of_document(const nlohmann::json& doc, const std::string& file);

}  // namespace cig
