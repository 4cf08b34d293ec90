#include "registry/engine_registry.hpp"

#include "common/error.hpp"
#include "quadtree/quadtree_engine.hpp"
#include "reference/reference_engine.hpp"
#include "segment/segment_engine.hpp"

namespace cig {

std::vector<std::string> engine_names() {
  return {"float", "segment", "segment-double", "quadtree", "quadtree-double"};
}

namespace {

std::unique_ptr<RasterEngine> make_named_engine(const std::string& name, const EngineOptions& options) {
  if (name == "float") return make_reference_engine(options);
  if (name == "segment") return make_segment_engine(options, false);
  if (name == "segment-double") return make_segment_engine(options, true);
  if (name == "quadtree") return make_quadtree_engine(options, false);
  if (name == "quadtree-double") return make_quadtree_engine(options, true);
  return nullptr;
}

}  // namespace

std::unique_ptr<RasterEngine> make_engine(const std::string& name, const EngineOptions& options) {
  if (auto engine = make_named_engine(name, options)) {
    engine->set_fan_split(options.fan_split);
    return engine;
  }
  std::string known;
  for (const auto& n : engine_names()) known += (known.empty() ? "" : ", ") + n;
  throw InputError("", "--engine", "unknown engine '" + name + "' (known: " + known + ")");
}

}  // namespace cig
