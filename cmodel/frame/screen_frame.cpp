#include "frame/screen_frame.hpp"

#include <charconv>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "common/json_reader.hpp"
#include "scene/polygon_checks.hpp"
#include "scene/scene_loader.hpp"

namespace cig {

namespace {

// The list's fields other than its polygons and light points.
ScreenFrame read_list_header(const JsonNode& root) {
  if (root.at("format").string() != "cig-polys")
    root.at("format").fail("must be \"cig-polys\" (a scene uses \"cig-scene\")");
  root.allow_only({"format", "version", "raster", "frame", "channel", "fog", "background", "polygons", "light_points"});
  if (root.at("version").integer() != 1) root.at("version").fail("only version 1 is supported");
  ScreenFrame f;
  if (auto r = root.find("raster")) {
    long long n = r->integer();
    if (!valid_raster_size(n))
      r->fail("raster size " + std::to_string(n) + " is not a power of two in [" + std::to_string(kMinRaster) + ", " +
              std::to_string(kMaxRaster) + "]");
    f.raster = int(n);
  }
  f.frame = root.find("frame") ? int(root.at("frame").integer(0, 10'000'000)) : 0;
  f.channel = root.find("channel") ? int(root.at("channel").integer(0, 7)) : 0;
  if (auto fg = root.find("fog")) {
    fg->allow_only({"colour", "start", "end"});
    f.fog.colour = fg->at("colour").colour();
    f.fog.start = fg->at("start").number(0, kMaxDistance);
    f.fog.end = fg->at("end").number(0, kMaxDistance);
    if (!(f.fog.end > f.fog.start)) fg->at("end").fail("fog end must be greater than fog start");
    f.background = f.fog.colour;
  }
  if (auto b = root.find("background")) f.background = b->colour();
  return f;
}

// One polygon of the list; `xy` is scratch space for the convexity check.
ScreenPolygon read_screen_polygon(const JsonNode& p, std::vector<glm::dvec2>& xy) {
  p.allow_only({"colour", "opaque", "protected", "vertices"});
  ScreenPolygon sp;
  if (auto c = p.find("colour")) sp.colour = c->colour();
  sp.opaque = p.boolean_or("opaque", true);
  sp.protect = p.boolean_or("protected", false);
  JsonNode vs = p.at("vertices");
  std::size_t nv = vs.array_size();
  if (nv < 3) vs.fail("polygon has " + std::to_string(nv) + " vertices; at least 3 are required");
  if (nv > std::size_t(kMaxScreenVertices))
    vs.fail("polygon has " + std::to_string(nv) + " vertices; at most " + std::to_string(kMaxScreenVertices) +
            " are accepted");
  sp.vertices.reserve(nv);
  xy.clear();
  for (std::size_t k = 0; k < nv; ++k) {
    JsonNode v = vs[k];
    v.array_size(4, 4);
    ScreenVertex sv;
    sv.xs = v[0].number(-1, 1);
    sv.ys = v[1].number(-1, 1);
    sv.zs = v[2].number(kMinListDepth, kMaxListDepth);
    sv.is = v[3].number(0, 1);
    sp.vertices.push_back(sv);
    xy.emplace_back(sv.xs, sv.ys);
  }
  std::string rule = check_convex_2d(xy);
  if (!rule.empty()) p.fail(rule);
  return sp;
}

// One light point of a list of `np` polygons.
ScreenLightPoint read_screen_light_point(const JsonNode& l, std::size_t np) {
  l.allow_only({"centre", "diameter", "colour", "intensity", "priority"});
  ScreenLightPoint lp;
  JsonNode c = l.at("centre");
  c.array_size(3, 3);
  lp.xs = c[0].number(-1, 1);
  lp.ys = c[1].number(-1, 1);
  lp.zs = c[2].number(kMinListDepth, kMaxListDepth);
  lp.ds = l.at("diameter").number(0, 1);
  if (auto col = l.find("colour")) lp.colour = col->colour();
  lp.intensity = l.find("intensity") ? l.at("intensity").number(0, 1) : 1.0;
  if (auto pr = l.find("priority")) lp.priority = std::int32_t(pr->integer(0, (long long)np));
  return lp;
}

}  // namespace

ScreenFrame polygon_list_of_document(const nlohmann::json& doc, const std::string& file,
                                     const PolygonListCheck& check) {
  JsonNode root(doc, file, "");
  ScreenFrame f = read_list_header(root);
  JsonNode polys = root.at("polygons");
  const std::size_t np = polys.array_size();
  const auto lps = root.find("light_points");
  // The counts are known: a caller's capacity refuses the list here, before any polygon is read.
  if (check) check(f, np, lps && lps->raw().is_array() ? lps->raw().size() : 0);
  f.polygons.reserve(np);
  std::vector<glm::dvec2> xy;
  for (std::size_t i = 0; i < np; ++i) f.polygons.push_back(read_screen_polygon(polys[i], xy));
  if (lps) {
    const std::size_t nl = lps->array_size();
    f.light_points.reserve(nl);
    for (std::size_t i = 0; i < nl; ++i) f.light_points.push_back(read_screen_light_point((*lps)[i], np));
  }
  return f;
}

ScreenFrame parse_polygon_list(const std::string& text, const std::string& file, const PolygonListCheck& check) {
  return polygon_list_of_document(parse_json_text(text, file), file, check);
}

ScreenFrame load_polygon_list(const std::string& file, const PolygonListCheck& check) {
  // The text is let go once parsed (the document holds all of it): the peak is text + document,
  // then document + frame, never the three.
  const nlohmann::json doc = parse_json_text(read_text_file(file), file);
  return polygon_list_of_document(doc, file, check);
}

namespace {

// A double as the polygon list writes it: all 17 digits, and negative zero as "-0.0" (a JSON
// reader takes "-0" for the integer 0 and would lose the sign, so the text would not round-trip).
struct Number {
  double x;
};
// "%.17g" through std::to_chars (the same text as the stream at precision 17 in the C locale,
// without the stream's locale and printf machinery per number: ~4,000 instructions each).
std::ostream& operator<<(std::ostream& s, Number n) {
  if (n.x == 0 && std::signbit(n.x)) return s << "-0.0";
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, n.x, std::chars_format::general, 17).ptr;
  return s.write(text, end - text);
}

}  // namespace

std::string polygon_list_json(const ScreenFrame& f) {
  // Written by hand rather than through nlohmann::json so that doubles keep all 17 digits and the
  // file round-trips bit for bit.
  std::ostringstream s;
  s << std::setprecision(17);
  auto rgb = [&](const Rgb& c) { s << "[" << Number{c.r} << ", " << Number{c.g} << ", " << Number{c.b} << "]"; };
  s << "{\n  \"format\": \"cig-polys\",\n  \"version\": 1,\n  \"raster\": " << f.raster << ",\n  \"frame\": " << f.frame
    << ",\n  \"channel\": " << f.channel << ",\n";
  if (f.fog.end < 1e29) {
    s << "  \"fog\": {\"colour\": ";
    rgb(f.fog.colour);
    s << ", \"start\": " << Number{f.fog.start} << ", \"end\": " << Number{f.fog.end} << "},\n";
  }
  s << "  \"background\": ";
  rgb(f.background);
  s << ",\n  \"polygons\": [";
  for (std::size_t i = 0; i < f.polygons.size(); ++i) {
    const auto& p = f.polygons[i];
    s << (i ? ",\n" : "\n") << "    {\"colour\": ";
    rgb(p.colour);
    s << ", \"opaque\": " << (p.opaque ? "true" : "false") << ", \"protected\": " << (p.protect ? "true" : "false")
      << ", \"vertices\": [";
    for (std::size_t k = 0; k < p.vertices.size(); ++k) {
      const auto& v = p.vertices[k];
      s << (k ? ", " : "") << "[" << Number{v.xs} << ", " << Number{v.ys} << ", " << Number{v.zs} << ", "
        << Number{v.is} << "]";
    }
    s << "]}";
  }
  s << "\n  ],\n  \"light_points\": [";
  for (std::size_t i = 0; i < f.light_points.size(); ++i) {
    const auto& l = f.light_points[i];
    s << (i ? ",\n" : "\n") << "    {\"centre\": [" << Number{l.xs} << ", " << Number{l.ys} << ", " << Number{l.zs}
      << "], \"diameter\": " << Number{l.ds} << ", \"colour\": ";
    rgb(l.colour);
    s << ", \"intensity\": " << Number{l.intensity} << ", \"priority\": " << l.priority << "}";
  }
  s << "\n  ]\n}\n";
  return s.str();
}

ScreenFrame concatenate_parts(const std::vector<ScreenFrame>& parts) {
  ScreenFrame f = parts.at(0);
  f.polygons.clear();
  f.light_points.clear();
  for (const ScreenFrame& p : parts) {
    const std::int32_t offset = std::int32_t(f.polygons.size());
    f.polygons.insert(f.polygons.end(), p.polygons.begin(), p.polygons.end());
    for (ScreenLightPoint l : p.light_points) {
      l.priority += offset;
      f.light_points.push_back(l);
    }
  }
  return f;
}

}  // namespace cig
