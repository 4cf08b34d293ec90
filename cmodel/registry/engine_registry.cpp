#include "registry/engine_registry.hpp"

#include <algorithm>

#include "common/error.hpp"
#include "invparam/invparam_engine.hpp"
#include "quadtree/quadtree_engine.hpp"
#include "reference/reference_engine.hpp"
#include "segment/segment_engine.hpp"

namespace cig {

namespace {

// One engine: what it models, and where its factory, settings and drop kinds come from.
struct EngineRow {
  const char* name;
  const char* models;
  bool bit_accurate, stage_f, pipelines, snap;
  std::unique_ptr<RasterEngine> (*make)(const EngineOptions&);
  std::vector<EngineOptionSpec> (*options)();
  const std::vector<DropKind>& (*drops)();
};

const std::vector<DropKind>& no_drops() {
  static const std::vector<DropKind> kNone;
  return kNone;
}

const std::vector<EngineRow>& engine_rows() {
  static const std::vector<EngineRow> rows{
      {"float", "the float reference (ground truth): a z-buffer on 1/Z, the seeds' Gouraud, fog and light points",
       false, false, false, true, [](const EngineOptions& o) { return make_reference_engine(o); },
       [] { return reference_engine_options(); }, no_drops},
      {"segment", "stages C and D: the formatter (eq. 1) and seed 001's segment processor", true, false, true, false,
       [](const EngineOptions& o) { return make_segment_engine(o, false); },
       [] { return segment_engine_options(false); }, segment_drop_kinds},
      {"segment-double", "stages C and D as `segment`, its kernels on double arithmetic (the twin)", false, false, true,
       false, [](const EngineOptions& o) { return make_segment_engine(o, true); },
       [] { return segment_engine_options(true); }, segment_drop_kinds},
      {"quadtree",
       "stages C and E: the formatter and seed 004's recursive-subdivision raster processor, clock by clock through "
       "its architecture",
       true, false, true, false, [](const EngineOptions& o) { return make_quadtree_engine(o, false); },
       [] { return quadtree_engine_options(false); }, no_drops},
      {"quadtree-double", "stages C and E as `quadtree`, its kernels on double arithmetic (the twin)", false, false,
       true, false, [](const EngineOptions& o) { return make_quadtree_engine(o, true); },
       [] { return quadtree_engine_options(true); }, no_drops},
      {"invparam", "stage F: seed 002's inverse-parameter visibility processor (1/t per sample, systolic array)", true,
       true, false, false, [](const EngineOptions& o) { return make_invparam_engine(o, false); },
       [] { return invparam_engine_options(false); }, invparam_drop_kinds},
      {"invparam-double", "stage F as `invparam`, on double arithmetic (the twin)", false, true, false, false,
       [](const EngineOptions& o) { return make_invparam_engine(o, true); },
       [] { return invparam_engine_options(true); }, invparam_drop_kinds}};
  return rows;
}

const EngineRow* find_row(const std::string& name) {
  for (const EngineRow& r : engine_rows())
    if (name == r.name) return &r;
  return nullptr;
}

[[noreturn]] void unknown_engine(const std::string& name) {
  std::string known;
  for (const auto& n : engine_names()) known += (known.empty() ? "" : ", ") + n;
  throw InputError("", "--engine", "unknown engine '" + name + "' (known: " + known + ")");
}

EngineInfo info_of(const EngineRow& r) {
  EngineInfo i{r.name, r.models,    r.bit_accurate, !r.stage_f,  r.stage_f,
               true,   r.pipelines, r.snap,         r.options(), r.drops()};
  // subpixel= is every engine's with a grid: the fixed engines' formatter, the float reference's --snap.
  if (!r.stage_f) i.options.push_back(subpixel_option(std::string(r.name) == "float"));
  for (const DropKind& d : i.drops) i.light_points = i.light_points && d.key != "light_points_not_drawn";
  return i;
}

// subpixel=B is every engine's that has a grid: it takes it out of the engine-specific settings.
// The float reference snaps to that grid itself (it needs --snap: unsnapped, it has no grid); the
// fixed engines get their input snapped to it before the formatter (RasterEngine::set_formatter_grid).
EngineOptions take_subpixel_option(const EngineRow& row, const EngineOptions& options) {
  EngineOptions o = options;
  const auto it = o.params.find("subpixel");
  if (it == o.params.end() || row.stage_f) return o;  // stage F's parser refuses it: no grid
  const bool is_float = std::string(row.name) == "float";
  o.subpixel_bits = parse_engine_options(row.name, {subpixel_option(is_float)}, {*it}).integer("subpixel");
  o.params.erase(it);
  if (is_float && !o.snap)
    throw InputError("", "--engine-opt",
                     "engine 'float': subpixel=" + std::to_string(o.subpixel_bits) +
                         " sets the grid the reference snaps to; add --snap (or use --reference float-snap)");
  return o;
}

}  // namespace

const std::vector<EngineInfo>& engine_infos() {
  static const std::vector<EngineInfo> infos = [] {
    std::vector<EngineInfo> v;
    for (const EngineRow& r : engine_rows()) v.push_back(info_of(r));
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
  for (const EngineRow& r : engine_rows()) names.push_back(r.name);
  return names;
}

std::vector<std::string> polygon_engine_names() {
  std::vector<std::string> names;
  for (const EngineRow& r : engine_rows())
    if (!r.stage_f) names.push_back(r.name);
  return names;
}

std::unique_ptr<RasterEngine> make_engine(const std::string& name, const EngineOptions& options) {
  const EngineRow* row = find_row(name);
  if (!row) unknown_engine(name);
  if (options.snap && !row->snap)
    throw InputError("", "--snap",
                     "--snap applies to the float engine; engine '" + name + "' " +
                         (row->stage_f ? "has no formatter grid (it works from eye-space planes)"
                                       : "snaps positions by itself, in its formatter"));
  parse_engine_options(name, engine_info(name).options, options.params);  // every key `cig engines` lists
  const EngineOptions o = take_subpixel_option(*row, options);
  std::unique_ptr<RasterEngine> engine = row->make(o);
  engine->set_fan_split(o.fan_split && !row->stage_f);  // stage F keeps polygon indices: EyeFace names them
  if (name != "float") engine->set_formatter_grid(o.subpixel_bits);
  return engine;
}

}  // namespace cig
