#include "scene/obj_loader.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "common/error.hpp"
#include "common/json_reader.hpp"
#include "scene/polygon_checks.hpp"

namespace cig {

namespace {

[[noreturn]] void fail(const std::string& file, std::size_t line, const std::string& rule) {
  throw InputError(file, "line " + std::to_string(line), rule);
}

double parse_coordinate(const std::string& tok, const std::string& file, std::size_t line) {
  const char* s = tok.c_str();
  char* end = nullptr;
  errno = 0;
  double x = std::strtod(s, &end);
  if (end == s || *end != '\0') fail(file, line, "'" + tok + "' is not a number");
  // ERANGE also flags underflow: a denormal such as 4.9e-324 is a valid (tiny) coordinate.
  if (!std::isfinite(x) || (errno == ERANGE && std::abs(x) >= 1))
    fail(file, line, "coordinate '" + tok + "' is not a finite number");
  if (std::abs(x) > kMaxWorldCoordinate)
    fail(file, line, "coordinate '" + tok + "' lies beyond the valid range of +-1e8 m");
  return x;
}

}  // namespace

ObjMesh parse_obj(const std::string& text, const std::string& file) {
  ObjMesh mesh;
  // A UTF-8 byte-order mark (written by some Windows exporters) is not part of the first statement.
  const bool bom = text.compare(0, 3, "\xEF\xBB\xBF") == 0;
  std::istringstream in(bom ? text.substr(3) : text);
  std::size_t face_statements = 0, first_degenerate_line = 0;
  std::string raw;
  std::size_t line = 0;
  while (std::getline(in, raw)) {
    ++line;
    if (!raw.empty() && raw.back() == '\r') raw.pop_back();
    std::istringstream ls(raw);
    std::string kw;
    if (!(ls >> kw) || kw[0] == '#') continue;
    if (kw == "v") {
      std::string t[3];
      if (!(ls >> t[0] >> t[1] >> t[2])) fail(file, line, "vertex needs three coordinates");
      mesh.vertices.emplace_back(parse_coordinate(t[0], file, line), parse_coordinate(t[1], file, line),
                                 parse_coordinate(t[2], file, line));
    } else if (kw == "f") {
      ++face_statements;
      std::vector<std::uint32_t> face;
      std::string tok;
      while (ls >> tok) {
        // "i", "i/t", "i//n" or "i/t/n": only the position index matters here.
        std::string idx = tok.substr(0, tok.find('/'));
        char* end = nullptr;
        long v = std::strtol(idx.c_str(), &end, 10);
        if (idx.empty() || *end != '\0') fail(file, line, "face index '" + tok + "' is not an integer");
        long n = long(mesh.vertices.size());
        long zero_based = v > 0 ? v - 1 : n + v;  // negative indices count back from the last vertex
        if (v == 0 || zero_based < 0 || zero_based >= n)
          fail(file, line,
               "face index " + std::to_string(v) + " refers to no vertex (" + std::to_string(n) + " defined so far)");
        face.push_back(std::uint32_t(zero_based));
      }
      if (face.size() < 3)
        fail(file, line, "face has " + std::to_string(face.size()) + " vertices; at least 3 are required");
      if (face.size() > 4)
        fail(file, line,
             "face has " + std::to_string(face.size()) + " vertices; only triangles and convex quads are accepted");
      std::vector<glm::dvec3> pts;
      for (auto i : face) pts.push_back(mesh.vertices[i]);
      std::string rule = check_convex_planar(pts);
      if (rule.rfind("polygon is degenerate", 0) == 0) {
        // Exported models often carry zero-area faces; they cover nothing, so they are skipped
        // (and counted) rather than rejected. Dents and warps are still errors.
        ++mesh.degenerate_faces;
        if (first_degenerate_line == 0) first_degenerate_line = line;
        continue;
      }
      if (!rule.empty()) fail(file, line, rule);
      mesh.faces.push_back(std::move(face));
      mesh.face_lines.push_back(line);
    }
    // Other statements (vt, vn, g, o, s, usemtl, mtllib, l, p) carry nothing this model uses.
  }
  if (face_statements == 0) throw InputError(file, "", "model has no faces (no 'f' statement)");
  if (mesh.faces.empty())
    throw InputError(file, "line " + std::to_string(first_degenerate_line),
                     "model has no faces: all " + std::to_string(face_statements) +
                         " faces are degenerate (zero area), the first on this line");
  return mesh;
}

ObjMesh load_obj(const std::string& file, long long max_bytes) {
  return parse_obj(read_text_file(file, max_bytes, "--max-model-mb"), file);
}

}  // namespace cig
