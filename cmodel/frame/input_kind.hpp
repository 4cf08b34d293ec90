// The two input formats of the commands that take either (compare, sweep, cosim): a scene
// ("cig-scene") or a polygon list ("cig-polys"), told apart by the document's top-level "format"
// field, never by searching the text (a scene may well name a channel "cig-polys").
#pragma once

#include <string>

namespace cig {

enum class InputKind { kScene, kPolygonList };

// Parses `text` (the contents of `file`); InputError when it is not JSON, not an object, or its
// "format" is neither.
InputKind input_kind(const std::string& text, const std::string& file);

}  // namespace cig
