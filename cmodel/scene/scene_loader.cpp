#include "scene/scene_loader.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>

#include <glm/geometric.hpp>

#include "common/json_reader.hpp"
#include "scene/model_loader.hpp"
#include "scene/polygon_checks.hpp"
#include "scene/polyhedron.hpp"

namespace cig {

bool valid_raster_size(long long n) { return n >= kMinRaster && n <= kMaxRaster && (n & (n - 1)) == 0; }

namespace {

// A world position or object-space point (metres): every component within the valid range.
glm::dvec3 read_point(const JsonNode& n) { return n.vec3(-kMaxWorldCoordinate, kMaxWorldCoordinate); }

// Heading, roll or yaw (degrees), default 0.
double read_angle(const JsonNode& n, const char* key) {
  auto a = n.find(key);
  return a ? a->number(-kMaxAngleDeg, kMaxAngleDeg) : 0.0;
}

// Heading, pitch and roll of a pose.
void read_attitude(const JsonNode& n, Pose& p) {
  p.heading_deg = read_angle(n, "heading");
  p.pitch_deg = n.find("pitch") ? n.at("pitch").number(-90, 90) : 0.0;
  p.roll_deg = read_angle(n, "roll");
}

Pose read_pose(const JsonNode& n) {
  Pose p;
  p.position = read_point(n.at("position"));
  read_attitude(n, p);
  return p;
}

// The sun direction normalised without overflow or underflow: scaled by its largest component first
// (so [1e200, -1e200, 0] and [1e-200, 0, 0] are directions like any other).
glm::dvec3 read_direction(const JsonNode& n) {
  glm::dvec3 d = n.vec3();
  const double largest = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
  if (largest == 0) n.fail("sun direction must not be the zero vector");
  // Directions of ordinary magnitude are normalised as given (their bits do not change).
  if (largest > 1e-150 && largest < 1e150) return glm::normalize(d);
  return glm::normalize(d / largest);
}

// Polygon attributes that a subobject may set once for all its polygons.
struct PolygonDefaults {
  Rgb colour{1, 1, 1};
  bool opaque = true;
  bool protect = false;
};

PolygonDefaults read_defaults(const JsonNode& n) {
  PolygonDefaults d;
  if (auto c = n.find("colour")) d.colour = c->colour();
  d.opaque = n.boolean_or("opaque", true);
  d.protect = n.boolean_or("protected", false);
  return d;
}

Polygon read_polygon(const JsonNode& n, const Subobject& sub, const PolygonDefaults& d) {
  n.allow_only({"indices", "colour", "opaque", "protected", "intensity"});
  Polygon p;
  JsonNode idx = n.at("indices");
  std::size_t count = idx.array_size();
  if (count < 3) idx.fail("polygon has " + std::to_string(count) + " vertices; at least 3 are required");
  if (count > std::size_t(kMaxSceneVertices))
    idx.fail("polygon has " + std::to_string(count) + " vertices; at most " + std::to_string(kMaxSceneVertices) +
             " are accepted (clipping may add " + std::to_string(kClipPlanes) + ")");
  std::vector<glm::dvec3> pts;
  for (std::size_t i = 0; i < count; ++i) {
    long long v = idx[i].integer();
    if (v < 0 || v >= (long long)sub.vertices.size())
      idx[i].fail("vertex index " + std::to_string(v) + " is out of range (subobject has " +
                  std::to_string(sub.vertices.size()) + " vertices)");
    p.indices.push_back(std::uint32_t(v));
    pts.push_back(sub.vertices[std::size_t(v)]);
  }
  std::string rule = check_convex_planar(pts);
  if (!rule.empty()) n.fail(rule);
  p.colour = d.colour;
  p.opaque = d.opaque;
  p.protect = d.protect;
  if (auto c = n.find("colour")) p.colour = c->colour();
  p.opaque = n.boolean_or("opaque", p.opaque);
  p.protect = n.boolean_or("protected", p.protect);
  if (auto in = n.find("intensity")) {
    p.self_lit = true;
    if (in->raw().is_array()) {
      in->array_size(count, count);
      for (std::size_t i = 0; i < count; ++i) p.self_intensity.push_back((*in)[i].number(0, 1));
    } else {
      p.self_intensity.assign(count, in->number(0, 1));
    }
  }
  return p;
}

// The factor a model's "unit" gives its coordinates: the length one unit of the file stands for.
double read_unit(const JsonNode& n) {
  static const std::pair<const char*, double> units[] = {{"m", 1},     {"cm", 0.01},   {"mm", 0.001},
                                                         {"km", 1000}, {"in", 0.0254}, {"ft", 0.3048}};
  const std::string u = n.string();
  for (const auto& [name, metres] : units)
    if (u == name) return metres;
  n.fail("unknown unit '" + u + "' (m, cm, mm, km, in, ft)");
}

ModelOptions read_model_options(const JsonNode& n, const SceneLimits& limits) {
  ModelOptions o;
  o.max_bytes = limits.max_model_bytes;
  o.seconds = limits.max_model_seconds;
  if (auto up = n.find("up")) {
    const std::string v = up->string();
    if (v != "y" && v != "z") up->fail("must be \"y\" or \"z\", is \"" + v + "\"");
    o.y_up = v == "y";
  }
  o.triangulate = n.boolean_or("triangulate", true);
  return o;
}

// The model a subobject names ('model', or its alias 'obj'), resolved against the scene's folder;
// any error in it is reported at the scene place that referenced it
// (objects[i].subobjects[j].model), with the model's own file and the mesh and face.
ModelMesh read_model(const JsonNode& n, const JsonNode& field, const std::string& scene_file,
                     const SceneLimits& limits) {
  const std::string path = field.string();
  if (path.empty()) field.fail("the model path is empty");
  if (path.find('\0') != std::string::npos) field.fail("the model path contains a NUL character");
  const ModelOptions options = read_model_options(n, limits);
  std::filesystem::path model = path;
  if (model.is_relative()) model = std::filesystem::path(scene_file).parent_path() / model;
  const std::string file = model.lexically_normal().string();
  try {
    return load_model(file, options);
  } catch (const InputError& e) {
    field.fail("model '" + path + "'" + (e.where().empty() ? "" : " " + e.where()) + ": " + e.rule());
  }
}

// A model subobject: the model's vertices as offset + scale x unit x v, its polygons with the
// subobject's colour, or the material's diffuse colour when the subobject gives none.
void read_model_subobject(const JsonNode& n, const std::string& scene_file, const SceneLimits& limits,
                          const PolygonDefaults& d, Subobject& s) {
  if (n.has("obj") && n.has("model")) n.fail("'obj' is an alias of 'model': give one of them");
  s.model_field = n.has("model") ? "model" : "obj";
  if (n.has("vertices") || n.has("polygons"))
    n.fail("a subobject takes either '" + s.model_field + "' or 'vertices' + 'polygons', not both");
  const glm::dvec3 offset = n.find("offset") ? read_point(n.at("offset")) : glm::dvec3(0);
  double scale = n.find("scale") ? n.at("scale").number(kMinModelScale, kMaxModelScale) : 1.0;
  if (auto u = n.find("unit")) scale *= read_unit(*u);
  const auto t0 = std::chrono::steady_clock::now();
  const ModelMesh mesh = read_model(n, n.at(s.model_field.c_str()), scene_file, limits);
  s.model = n.at(s.model_field.c_str()).string();
  s.model_meshes = mesh.mesh_names;
  s.model_summary = mesh.summary;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const glm::dvec3 v = offset + scale * mesh.vertices[i];
    if (!(std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}) <= kMaxWorldCoordinate))
      n.at(s.model_field.c_str())
          .fail("model '" + s.model + "': vertex " + std::to_string(i) + " at (" + std::to_string(v.x) + ", " +
                std::to_string(v.y) + ", " + std::to_string(v.z) + ") scaled and offset lies beyond " +
                std::to_string(kMaxWorldCoordinate) + " m");
    s.vertices.push_back(v);
  }
  const bool own_colour = n.has("colour");
  for (const ModelFace& f : mesh.faces) {
    s.model_faces.push_back(f.place);
    Polygon p;
    p.indices = f.indices;
    p.colour = own_colour || !f.has_colour ? d.colour : f.colour;
    p.opaque = d.opaque;
    p.protect = d.protect;
    s.polygons.push_back(std::move(p));
  }
  s.model_summary.load_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

Subobject read_subobject(const JsonNode& n, const std::string& scene_file, const SceneLimits& limits) {
  n.allow_only({"name", "vertices", "polygons", "model", "obj", "offset", "scale", "unit", "up", "triangulate",
                "crease_angle", "colour", "opaque", "protected", "priority_order"});
  Subobject s;
  if (auto nm = n.find("name")) s.name = nm->string();
  // A model file's face order is nobody's priority order; an inline list is the modeller's.
  s.priority_tree = n.has("model") || n.has("obj");
  if (auto po = n.find("priority_order")) {
    const std::string v = po->string();
    if (v != "modeller" && v != "tree") po->fail("must be \"modeller\" or \"tree\", is \"" + v + "\"");
    s.priority_tree = v == "tree";
  }
  s.crease_angle_deg = n.find("crease_angle") ? n.at("crease_angle").number(0, 180) : 50.0;
  PolygonDefaults d = read_defaults(n);
  if (n.has("model") || n.has("obj")) {
    read_model_subobject(n, scene_file, limits, d, s);
  } else {
    for (const char* key : {"offset", "scale", "unit", "up", "triangulate"})
      if (n.has(key)) n.at(key).fail(std::string("'") + key + "' applies only to model subobjects");
    JsonNode verts = n.at("vertices");
    std::size_t nv = verts.array_size();
    if (nv < 3) verts.fail("a subobject needs at least 3 vertices");
    for (std::size_t i = 0; i < nv; ++i) s.vertices.push_back(read_point(verts[i]));
    JsonNode polys = n.at("polygons");
    std::size_t np = polys.array_size();
    if (np == 0) polys.fail("a subobject needs at least one polygon");
    for (std::size_t i = 0; i < np; ++i) s.polygons.push_back(read_polygon(polys[i], s, d));
  }
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const auto& v : s.vertices) {
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  s.centre = 0.5 * (lo + hi);
  return s;
}

// A half-width of a light's lobe: (0, 180] degrees.
double read_half_width(const JsonNode& n) {
  const double v = n.number(0, kMaxLobeHalfWidthDeg);
  if (!(v > 0)) n.fail("beam half-width must be positive");
  return v;
}

// A directional light's lobe: the axis (heading as a pose's, elevation above the object's
// horizontal, both default 0) and the half-widths of its ellipse (required).
LightBeam read_light_beam(const JsonNode& n) {
  n.allow_only({"heading", "elevation", "horizontal", "vertical"});
  LightBeam b;
  b.heading_deg = read_angle(n, "heading");
  b.elevation_deg = n.find("elevation") ? n.at("elevation").number(-90, 90) : 0.0;
  b.horizontal_deg = read_half_width(n.at("horizontal"));
  b.vertical_deg = read_half_width(n.at("vertical"));
  b.frame = body_to_world(b.heading_deg, 0, 0);  // right, along the azimuth, up
  return b;
}

// A PAPI/VASI unit's colour below its transition angle (both required).
LightBelow read_light_below(const JsonNode& n) {
  n.allow_only({"elevation", "colour"});
  LightBelow b;
  b.elevation_deg = n.at("elevation").number(-90, 90);
  b.colour = n.at("colour").colour();
  return b;
}

LightPoint read_light_point(const JsonNode& n) {
  n.allow_only({"position", "diameter", "colour", "intensity", "beam", "below"});
  LightPoint l;
  l.position = read_point(n.at("position"));
  l.diameter = n.at("diameter").number(0, kMaxLightDiameter);
  if (!(l.diameter > 0)) n.at("diameter").fail("light-point diameter must be positive");
  if (auto c = n.find("colour")) l.colour = c->colour();
  if (auto i = n.find("intensity")) l.intensity = i->number(0, 1);
  if (auto b = n.find("beam")) l.beam = read_light_beam(*b);
  if (auto b = n.find("below")) l.below = read_light_below(*b);
  return l;
}

// A "polyhedron": true object's rules (scene/polyhedron.hpp), reported at the polygon that breaks
// them: its JSON path, or for a model its 'model' field with the model's file, mesh and face.
void check_polyhedron(const JsonNode& n, Object& o) {
  const PolyhedronIssue issue = build_polyhedron(o);
  if (issue.rule.empty()) return;
  const std::string rule = (o.name.empty() ? std::string("object") : "object '" + o.name + "'") + ": " + issue.rule;
  if (issue.subobject < 0) n.fail(rule);
  const JsonNode sub = n.at("subobjects")[std::size_t(issue.subobject)];
  const Subobject& s = o.subobjects[std::size_t(issue.subobject)];
  if (s.model.empty()) sub.at("polygons")[std::size_t(issue.polygon)].fail(rule);
  sub.at(s.model_field.c_str())
      .fail("model '" + s.model + "' " + model_face_place(s, std::size_t(issue.polygon)) + ": " + rule);
}

Object read_object(const JsonNode& n, const std::string& scene_file, const SceneLimits& limits) {
  n.allow_only({"name", "position", "heading", "pitch", "roll", "layer", "subobject_order", "bounding_sphere",
                "subobjects", "light_points", "polyhedron"});
  Object o;
  if (auto nm = n.find("name")) o.name = nm->string();
  if (auto l = n.find("layer")) o.layer = int(l->integer(-8, 8));
  if (auto so = n.find("subobject_order")) {
    const std::string v = so->string();
    if (v != "database" && v != "distance") so->fail("must be \"database\" or \"distance\", is \"" + v + "\"");
    o.subobjects_by_distance = v == "distance";
  }
  if (n.has("position")) o.pose = read_pose(n);
  else read_attitude(n, o.pose);
  if (auto subs = n.find("subobjects")) {
    std::size_t ns = subs->array_size();
    for (std::size_t i = 0; i < ns; ++i) o.subobjects.push_back(read_subobject((*subs)[i], scene_file, limits));
  }
  if (auto lps = n.find("light_points")) {
    std::size_t nl = lps->array_size();
    for (std::size_t i = 0; i < nl; ++i) o.light_points.push_back(read_light_point((*lps)[i]));
  }
  if (o.subobjects.empty() && o.light_points.empty()) n.fail("an object needs at least one subobject or light point");
  o.polyhedron = n.boolean_or("polyhedron", false);
  if (o.polyhedron) check_polyhedron(n, o);

  // Bounding sphere in object coordinates: the scene manager culls with it, so it must enclose
  // every vertex and light point (a visible object must never be flagged invisible).
  if (auto bs = n.find("bounding_sphere")) {
    bs->allow_only({"centre", "radius"});
    o.sphere_centre = read_point(bs->at("centre"));
    o.sphere_radius = bs->at("radius").number(0, kMaxDistance);
    o.sphere_given = true;
    const double slack = 1e-9 * std::max(1.0, o.sphere_radius);
    for (std::size_t si = 0; si < o.subobjects.size(); ++si)
      for (const auto& v : o.subobjects[si].vertices)
        if (glm::length(v - o.sphere_centre) > o.sphere_radius + slack)
          bs->fail("bounding sphere does not enclose every vertex (subobject " + std::to_string(si) + " reaches " +
                   std::to_string(glm::length(v - o.sphere_centre)) + " from the centre)");
    for (const auto& l : o.light_points)
      if (glm::length(l.position - o.sphere_centre) > o.sphere_radius + slack)
        bs->fail("bounding sphere does not enclose every light point");
  } else {
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const auto& s : o.subobjects)
      for (const auto& v : s.vertices) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
      }
    for (const auto& l : o.light_points) {
      lo = glm::min(lo, l.position);
      hi = glm::max(hi, l.position);
    }
    o.sphere_centre = 0.5 * (lo + hi);
    double r = 0;
    for (const auto& s : o.subobjects)
      for (const auto& v : s.vertices) r = std::max(r, glm::length(v - o.sphere_centre));
    for (const auto& l : o.light_points) r = std::max(r, glm::length(l.position - o.sphere_centre));
    o.sphere_radius = r * (1 + 1e-12);
  }
  return o;
}

void read_channels(const JsonNode& root, Scene& s) {
  JsonNode chans = root.at("channels");
  std::size_t nc = chans.array_size();
  if (nc < 1 || nc > 8) chans.fail("a scene has 1 to 8 channels, found " + std::to_string(nc));
  for (std::size_t i = 0; i < nc; ++i) {
    JsonNode c = chans[i];
    c.allow_only({"name", "yaw", "pitch", "fov"});
    Channel ch;
    ch.name = c.find("name") ? c.at("name").string() : "ch" + std::to_string(i);
    ch.yaw_deg = read_angle(c, "yaw");
    ch.pitch_deg = c.find("pitch") ? c.at("pitch").number(-90, 90) : 0.0;
    double fov = c.at("fov").number();
    if (!(fov > 0)) c.at("fov").fail("field of view must be positive, is " + std::to_string(fov));
    if (!(fov < 170)) c.at("fov").fail("field of view must be below 170 degrees, is " + std::to_string(fov));
    ch.fov_deg = fov;
    s.channels.push_back(ch);
  }
}

// Lighting, fog and background.
void read_environment(const JsonNode& root, Scene& s) {
  if (auto l = root.find("lighting")) {
    l->allow_only({"sun_direction", "sun_intensity", "ambient"});
    s.lighting.sun_direction = read_direction(l->at("sun_direction"));
    if (l->has("sun_intensity")) s.lighting.sun_intensity = l->at("sun_intensity").number(0, 1);
    if (l->has("ambient")) s.lighting.ambient = l->at("ambient").number(0, 1);
  }
  bool has_fog = false;
  if (auto f = root.find("fog")) {
    f->allow_only({"colour", "start", "end"});
    s.fog.colour = f->at("colour").colour();
    s.fog.start = f->at("start").number(0, kMaxDistance);
    s.fog.end = f->at("end").number(0, kMaxDistance);
    if (!(s.fog.end > s.fog.start)) f->at("end").fail("fog end must be greater than fog start");
    has_fog = true;
  }
  s.background = has_fog ? s.fog.colour : Rgb(0);
  if (auto b = root.find("background")) s.background = b->colour();
}

void read_observer(const JsonNode& root, Scene& s) {
  JsonNode obs = root.at("observer");
  obs.allow_only({"keyframes"});
  JsonNode kfs = obs.at("keyframes");
  std::size_t nk = kfs.array_size();
  if (nk == 0) kfs.fail("the observer path needs at least one keyframe");
  for (std::size_t i = 0; i < nk; ++i) {
    JsonNode k = kfs[i];
    k.allow_only({"frame", "position", "heading", "pitch", "roll"});
    Keyframe kf;
    kf.frame = int(k.at("frame").integer(0, 10'000'000));
    kf.pose = read_pose(k);
    if (i == 0 && kf.frame != 0) k.at("frame").fail("the first keyframe must be at frame 0");
    if (i > 0 && kf.frame <= s.keyframes.back().frame)
      k.at("frame").fail("keyframe frames must be strictly increasing");
    s.keyframes.push_back(kf);
  }
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& file, const SceneLimits& limits) {
  return scene_of_document(parse_json_text(text, file), file, limits);
}

Scene scene_of_document(const nlohmann::json& doc, const std::string& file, const SceneLimits& limits) {
  JsonNode root(doc, file, "");
  if (root.at("format").string() != "cig-scene")
    root.at("format").fail("must be \"cig-scene\" (a polygon list uses \"cig-polys\")");
  // "provenance": how a tool made the scene (cig import writes it); recorded, not read.
  root.allow_only({"format", "version", "provenance", "name", "raster", "view", "channels", "lighting", "fog",
                   "background", "observer", "objects"});
  if (root.at("version").integer() != 1) root.at("version").fail("only version 1 is supported");

  Scene s;
  s.file = file;
  if (auto nm = root.find("name")) s.name = nm->string();
  if (auto r = root.find("raster")) {
    long long n = r->integer();
    if (!valid_raster_size(n))
      r->fail("raster size " + std::to_string(n) + " is not a power of two in [" + std::to_string(kMinRaster) + ", " +
              std::to_string(kMaxRaster) + "]");
    s.raster = int(n);
  }
  if (auto v = root.find("view")) {
    v->allow_only({"near", "range", "light_point_min_diameter"});
    if (v->has("near")) s.near = v->at("near").number(kMinNear, kMaxNear);
    if (v->has("range")) {
      s.range = v->at("range").number(kMinNear, 1e9);
      if (!(s.range > s.near)) v->at("range").fail("the visibility range must lie beyond the near plane");
    }
    if (v->has("light_point_min_diameter"))
      s.light_rendering.min_diameter_units = v->at("light_point_min_diameter").number(0, 7);
  }

  read_channels(root, s);
  read_environment(root, s);
  read_observer(root, s);
  JsonNode objs = root.at("objects");
  std::size_t no = objs.array_size();
  for (std::size_t i = 0; i < no; ++i) s.objects.push_back(read_object(objs[i], file, limits));
  s.priority = compile_priorities(s, limits.priority);
  return s;
}

Scene load_scene(const std::string& file, const SceneLimits& limits) {
  // The text is let go once parsed: the scene is read from the document alone.
  const nlohmann::json doc = parse_json_text(read_text_file(file), file);
  return scene_of_document(doc, file, limits);
}

}  // namespace cig
