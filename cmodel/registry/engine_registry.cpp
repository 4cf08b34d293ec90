#include "registry/engine_registry.hpp"

#include <algorithm>

#include "common/error.hpp"
#include "invparam/invparam_engine.hpp"
#include "quadtree/quadtree_engine.hpp"
#include "reference/reference_engine.hpp"
#include "segment/segment_engine.hpp"

namespace cig {

namespace {

// Every engine's declaration (engine/engine_declaration.hpp), in the order --engine lists them:
// the one list a new engine joins.
const std::vector<const EngineDeclaration*>& engine_rows() {
  static const std::vector<const EngineDeclaration*> rows{
      &reference_engine_declaration(),     &segment_engine_declaration(false), &segment_engine_declaration(true),
      &quadtree_engine_declaration(false), &quadtree_engine_declaration(true), &invparam_engine_declaration(false),
      &invparam_engine_declaration(true)};
  return rows;
}

const EngineDeclaration* find_row(const std::string& name) {
  for (const EngineDeclaration* r : engine_rows())
    if (name == r->name) return r;
  return nullptr;
}

// A grid subpixel=B can set: the formatter's, or the one the reference snaps to (stage F has none).
bool has_grid(const EngineDeclaration& r) { return r.can.formatter || r.can.reference; }

[[noreturn]] void unknown_engine(const std::string& name) {
  std::string known;
  for (const auto& n : engine_names()) known += (known.empty() ? "" : ", ") + n;
  throw InputError("", "--engine", "unknown engine '" + name + "' (known: " + known + ")");
}

EngineInfo info_of(const EngineDeclaration& r) {
  EngineInfo i{r.name, r.models, r.can, true, r.options(), r.drops()};
  // subpixel= is every engine's with a grid: the formatter's, or the grid the reference snaps to.
  if (has_grid(r)) i.options.push_back(subpixel_option(r.can.reference));
  for (const DropKind& d : i.drops) i.light_points = i.light_points && d.key != "light_points_not_drawn";
  return i;
}

// subpixel=B is every engine's that has a grid: it takes it out of the engine-specific settings.
// The float reference snaps to that grid itself (it needs --snap: unsnapped, it has no grid); the
// fixed engines get their input snapped to it before the formatter (RasterEngine::set_formatter_grid).
EngineOptions take_subpixel_option(const EngineDeclaration& row, const EngineOptions& options) {
  EngineOptions o = options;
  const auto it = o.params.find("subpixel");
  if (it == o.params.end() || !has_grid(row)) return o;  // stage F's parser refuses it: no grid
  o.subpixel_bits = parse_engine_options(row.name, {subpixel_option(row.can.reference)}, {*it}).integer("subpixel");
  o.params.erase(it);
  if (row.can.reference && !o.snap)
    throw InputError("", "--engine-opt",
                     std::string("engine '") + row.name + "': subpixel=" + std::to_string(o.subpixel_bits) +
                         " sets the grid the reference snaps to; add --snap (or use --reference " + row.name +
                         "-snap)");
  return o;
}

}  // namespace

const std::vector<EngineInfo>& engine_infos() {
  static const std::vector<EngineInfo> infos = [] {
    std::vector<EngineInfo> v;
    for (const EngineDeclaration* r : engine_rows()) v.push_back(info_of(*r));
    return v;
  }();
  return infos;
}

const EngineInfo& engine_info(const std::string& name) {
  for (const EngineInfo& i : engine_infos())
    if (i.name == name) return i;
  unknown_engine(name);
}

std::vector<std::string> engine_names() {
  std::vector<std::string> names;
  for (const EngineDeclaration* r : engine_rows()) names.push_back(r->name);
  return names;
}

std::vector<std::string> polygon_engine_names() {
  std::vector<std::string> names;
  for (const EngineDeclaration* r : engine_rows())
    if (r->can.polygons) names.push_back(r->name);
  return names;
}

// The declaration of `name` with `options` checked against its table and capabilities.
const EngineDeclaration& checked_row(const std::string& name, const EngineOptions& options) {
  const EngineDeclaration* row = find_row(name);
  if (!row) unknown_engine(name);
  if (options.snap && !row->can.reference)
    throw InputError("", "--snap",
                     "--snap applies to the reference engine (" + reference_engine_name() + "); engine '" + name +
                         "' " +
                         (row->can.formatter ? "snaps positions by itself, in its formatter"
                                             : "has no formatter grid (it works from eye-space planes)"));
  parse_engine_options(name, engine_info(name).options, options.params);  // every key `cig engines` lists
  return *row;
}

void check_engine_options(const std::string& name, const EngineOptions& options) {
  take_subpixel_option(checked_row(name, options), options);
}

std::unique_ptr<RasterEngine> make_engine(const std::string& name, const EngineOptions& options) {
  const EngineDeclaration& row = checked_row(name, options);
  const EngineOptions o = take_subpixel_option(row, options);
  std::unique_ptr<RasterEngine> engine = row.make(o);
  engine->set_fan_split(o.fan_split && row.can.polygons);  // stage F keeps polygon indices: EyeFace names them
  if (row.can.formatter) engine->set_formatter_grid(o.subpixel_bits);
  return engine;
}

std::string reference_engine_name() {
  for (const EngineDeclaration* r : engine_rows())
    if (r->can.reference) return r->name;
  throw std::logic_error("no engine declares itself the reference");
}

}  // namespace cig
