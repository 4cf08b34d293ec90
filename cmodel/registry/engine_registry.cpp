#include "registry/engine_registry.hpp"

#include <algorithm>

#include "common/error.hpp"
#include "invparam/invparam_engine.hpp"
#include "quadtree/quadtree_engine.hpp"
#include "reference/reference_engine.hpp"
#include "segment/segment_engine.hpp"

namespace cig {

std::vector<std::string> engine_names() {
  return {"float", "segment", "segment-double", "quadtree", "quadtree-double", "invparam", "invparam-double"};
}

std::vector<std::string> polygon_engine_names() {
  std::vector<std::string> names = engine_names();
  names.erase(
      std::remove_if(names.begin(), names.end(), [](const std::string& n) { return n.rfind("invparam", 0) == 0; }),
      names.end());
  return names;
}

namespace {

std::unique_ptr<RasterEngine> make_named_engine(const std::string& name, const EngineOptions& options) {
  if (name == "float") return make_reference_engine(options);
  if (name == "segment") return make_segment_engine(options, false);
  if (name == "segment-double") return make_segment_engine(options, true);
  if (name == "quadtree") return make_quadtree_engine(options, false);
  if (name == "quadtree-double") return make_quadtree_engine(options, true);
  if (name == "invparam") return make_invparam_engine(options, false);
  if (name == "invparam-double") return make_invparam_engine(options, true);
  return nullptr;
}

}  // namespace

namespace {

// Stage F's engines draw the frame's polyhedra: the polygons keep their indices (no fan split,
// EyeFace::polygon names them) and there is no formatter.
bool is_stage_f(const std::string& name) { return name == "invparam" || name == "invparam-double"; }

// subpixel=B is every engine's: it takes it out of the engine-specific settings. The float
// reference snaps to that grid itself (it needs --snap: unsnapped, it has no grid); the fixed
// engines get their input snapped to it before the formatter (RasterEngine::set_formatter_grid).
EngineOptions take_subpixel_option(const std::string& name, const EngineOptions& options) {
  EngineOptions o = options;
  const auto it = o.params.find("subpixel");
  if (it == o.params.end()) return o;
  o.subpixel_bits = subpixel_bits_option(it->second);
  o.params.erase(it);
  if (is_stage_f(name))
    throw InputError(
        "", "--engine-opt",
        "engine '" + name + "' takes no subpixel= (stage F has no formatter grid: it works from eye-space planes)");
  if (name == "float" && !o.snap)
    throw InputError("", "--engine-opt",
                     "engine 'float': subpixel=" + std::to_string(o.subpixel_bits) +
                         " sets the grid the reference snaps to; add --snap (or use --reference float-snap)");
  return o;
}

}  // namespace

std::unique_ptr<RasterEngine> make_engine(const std::string& name, const EngineOptions& options) {
  const EngineOptions o = take_subpixel_option(name, options);
  if (auto engine = make_named_engine(name, o)) {
    engine->set_fan_split(o.fan_split && !is_stage_f(name));
    if (name != "float") engine->set_formatter_grid(o.subpixel_bits);
    return engine;
  }
  std::string known;
  for (const auto& n : engine_names()) known += (known.empty() ? "" : ", ") + n;
  throw InputError("", "--engine", "unknown engine '" + name + "' (known: " + known + ")");
}

}  // namespace cig
