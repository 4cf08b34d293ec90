#include "scene/model_loader.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <utility>

#include <assimp/DefaultIOSystem.h>
#include <assimp/MemoryIOWrapper.h>
#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "common/byte_record.hpp"
#include "common/error.hpp"
#include "common/isolated_call.hpp"
#include "common/json_reader.hpp"
#include "scene/polygon_checks.hpp"

namespace cig {

namespace {

using Triangle = std::array<std::uint32_t, 3>;
using Faces = std::vector<std::vector<std::uint32_t>>;

// A model larger than this many polygons is refused: a small file can instance one mesh in many
// nodes, and the flattened model must fit in memory.
constexpr std::size_t kMaxModelPolygons = std::size_t(1) << 24;

// Every file assimp opens passes the checks the scene loader makes on its own inputs (a regular
// file, at most the model limit) before a byte of it is read: the model itself and the files it
// names (an OBJ's .mtl, a glTF's .bin). assimp treats a file it cannot open as missing and may go
// on without it, so the first refusal is kept and reported after the import.
constexpr const char* kBom = "\xEF\xBB\xBF";

class CheckedIOSystem : public Assimp::DefaultIOSystem {
 public:
  CheckedIOSystem(long long max_bytes, bool allow_files) : max_bytes_(max_bytes), allow_files_(allow_files) {}

  bool Exists(const char* file) const override {
    std::error_code ec;
    return allow_files_ && std::filesystem::exists(file, ec);
  }

  Assimp::IOStream* Open(const char* file, const char* mode) override {
    if (!allow_files_ || std::strpbrk(mode, "wa+") != nullptr) return nullptr;  // read only
    std::error_code ec;
    // A missing .mtl or texture is the exporter's omission, which assimp works around (default
    // material): no refusal. What exists must be a regular file within the limit.
    if (!std::filesystem::exists(std::filesystem::symlink_status(file, ec)) && !std::filesystem::exists(file, ec))
      return nullptr;
    try {
      check_input_file(file, max_bytes_, "--max-model-mb");
    } catch (const InputError& e) {
      if (refusal_.empty()) refusal_ = e.what();
      return nullptr;
    }
    if (file == bom_file_) return without_bom(file, mode);
    return DefaultIOSystem::Open(file, mode);
  }

  const std::string& refusal() const { return refusal_; }
  // A UTF-8 byte-order mark (written by some Windows exporters) is not part of the first
  // statement; assimp 5.2's OBJ importer would take "<BOM>v" for an unknown keyword and drop the
  // first vertex, so the mark is removed before it reads `file`.
  void strip_bom(const std::string& file) { bom_file_ = file; }

 private:
  Assimp::IOStream* without_bom(const char* file, const char* mode) {
    const std::string text = read_text_file(file, max_bytes_, "--max-model-mb");
    if (text.compare(0, 3, kBom) != 0) return DefaultIOSystem::Open(file, mode);
    auto* bytes = new std::uint8_t[text.size() - 3];
    std::memcpy(bytes, text.data() + 3, text.size() - 3);
    return new Assimp::MemoryIOStream(bytes, text.size() - 3, true);  // the stream owns the bytes
  }

  long long max_bytes_;
  bool allow_files_;
  std::string refusal_, bom_file_;
};

bool is_obj(const std::string& name) {
  const std::string ext = std::filesystem::path(name).extension().string();
  return ext.size() == 4 && std::tolower(ext[1]) == 'o' && std::tolower(ext[2]) == 'b' && std::tolower(ext[3]) == 'j';
}

void configure(Assimp::Importer& im) {
  // Coordinates as the file writes them, for Collada as for every format (assimp would otherwise
  // turn a Z_UP file y-up): the subobject's "up" says which axis is up.
  im.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  // A file without meshes is an error, not a stick figure drawn from its bones.
  im.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);
}

// assimp's own message, with the model file; or the refusal of a file the model names.
[[noreturn]] void import_failed(const std::string& file, const Assimp::Importer& im, const CheckedIOSystem& io) {
  if (!io.refusal().empty()) throw InputError(file, "", "a file the model reads is refused: " + io.refusal());
  throw InputError(file, "", std::string("assimp: ") + im.GetErrorString());
}

std::string place(const aiScene& s, std::uint32_t mesh, std::size_t face) {
  const std::string name = s.mMeshes[mesh]->mName.C_Str();
  return (name.empty() ? "mesh " + std::to_string(mesh) : "mesh '" + name + "'") + " face " + std::to_string(face);
}

Faces copy_faces(const aiMesh& m) {
  Faces faces(m.mNumFaces);
  for (unsigned f = 0; f < m.mNumFaces; ++f)
    faces[f].assign(m.mFaces[f].mIndices, m.mFaces[f].mIndices + m.mFaces[f].mNumIndices);
  return faces;
}

// Why the face must be triangulated: more corners than the pipeline takes, a dent or a warp. Empty
// otherwise: the face is taken as it is, or skipped (zero area), or refused when it is not simple
// (a bow-tie has no triangulation that draws what the modeller meant).
std::string needs_triangulation(const aiMesh& m, const std::vector<std::uint32_t>& face) {
  if (face.size() > std::size_t(kMaxSceneVertices))
    return "face has " + std::to_string(face.size()) + " vertices; at most " + std::to_string(kMaxSceneVertices) +
           " are accepted";
  std::vector<glm::dvec3> pts;
  for (auto i : face) pts.emplace_back(m.mVertices[i].x, m.mVertices[i].y, m.mVertices[i].z);
  // Convexity and planarity survive the node transforms (affine maps), so the file's own
  // coordinates decide.
  const std::string rule = check_convex_planar(pts);
  return rule.rfind("polygon is not convex", 0) == 0 || rule.rfind("polygon is not planar", 0) == 0 ? rule
                                                                                                    : std::string();
}

// assimp's triangulation replaces each face of n > 3 corners in place by up to n - 2 triangles
// (fewer when it finds no ear: a face that is not simple) and keeps points, lines and triangles
// one for one (a triangle's corners possibly rotated). So the triangles of face f are the next
// ones whose corners are all corners of f. Returns, per face, the triangles that replace it
// (empty for the faces the pipeline takes as they are).
std::vector<std::vector<Triangle>> match_triangles(const aiScene& s, std::uint32_t mi, const Faces& before,
                                                   const std::vector<char>& needed, const std::string& file) {
  const aiMesh& after = *s.mMeshes[mi];
  std::vector<std::vector<Triangle>> split(before.size());
  unsigned j = 0;
  for (std::size_t f = 0; f < before.size(); ++f) {
    const auto& face = before[f];
    if (face.size() <= 3) {
      ++j;
      continue;
    }
    std::size_t taken = 0;
    for (; j < after.mNumFaces && taken < face.size() - 2 && after.mFaces[j].mNumIndices == 3; ++j, ++taken) {
      const unsigned* t = after.mFaces[j].mIndices;
      if (!std::all_of(t, t + 3, [&](unsigned i) { return std::find(face.begin(), face.end(), i) != face.end(); }))
        break;
      if (needed[f]) split[f].push_back({t[0], t[1], t[2]});
    }
    if (needed[f] && taken != face.size() - 2)
      throw InputError(file, place(s, mi, f),
                       "assimp could not triangulate the face (" + std::to_string(taken) + " triangles for " +
                           std::to_string(face.size()) + " corners: it is not a simple polygon)");
  }
  return split;
}

// The faces of every mesh as the file gives them, and the triangles that replace those the
// pipeline cannot take (assimp's aiProcess_Triangulate, applied only when a face needs it, so that
// convex planar polygons of up to kMaxSceneVertices corners stay whole, as the hardware draws them).
struct MeshFaces {
  std::vector<Faces> faces;
  std::vector<std::vector<std::vector<Triangle>>> split;
};

MeshFaces triangulate(Assimp::Importer& im, const CheckedIOSystem& io, const std::string& file,
                      const ModelOptions& options, ModelSummary& summary) {
  const aiScene* s = im.GetScene();
  MeshFaces mf;
  std::vector<std::vector<char>> needed(s->mNumMeshes);
  bool any = false;
  for (unsigned mi = 0; mi < s->mNumMeshes; ++mi) {
    mf.faces.push_back(copy_faces(*s->mMeshes[mi]));
    needed[mi].assign(mf.faces[mi].size(), 0);
    for (std::size_t f = 0; f < mf.faces[mi].size(); ++f) {
      if (mf.faces[mi][f].size() < 3) continue;
      const std::string rule = needs_triangulation(*s->mMeshes[mi], mf.faces[mi][f]);
      if (rule.empty()) continue;
      if (!options.triangulate)
        throw InputError(file, place(*s, mi, f), rule + " (the subobject sets \"triangulate\": false)");
      needed[mi][f] = 1;
      ++summary.triangulated_faces;
      any = true;
    }
  }
  mf.split.resize(s->mNumMeshes);
  if (!any) return mf;
  s = im.ApplyPostProcessing(aiProcess_Triangulate);
  if (!s) import_failed(file, im, io);
  for (unsigned mi = 0; mi < s->mNumMeshes; ++mi)
    mf.split[mi] = match_triangles(*s, mi, mf.faces[mi], needed[mi], file);
  return mf;
}

glm::dmat4 to_glm(const aiMatrix4x4& a) {
  glm::dmat4 m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m[c][r] = double(a[r][c]);  // aiMatrix4x4 is row-major, glm column-major
  return m;
}

// The diffuse colour of the mesh's material, clamped to [0, 1] (exporters write slightly
// out-of-range colours); none for assimp's default material, which it invents for files without
// materials (grey), so that such a model keeps the subobject's default colour, white.
bool material_colour(const aiScene& s, const aiMesh& m, Rgb& colour) {
  if (m.mMaterialIndex >= s.mNumMaterials) return false;
  const aiMaterial& mat = *s.mMaterials[m.mMaterialIndex];
  aiString name;
  if (mat.Get(AI_MATKEY_NAME, name) == AI_SUCCESS && std::strcmp(name.C_Str(), AI_DEFAULT_MATERIAL_NAME) == 0)
    return false;
  aiColor3D d;
  if (mat.Get(AI_MATKEY_COLOR_DIFFUSE, d) != AI_SUCCESS) return false;
  if (!std::isfinite(d.r) || !std::isfinite(d.g) || !std::isfinite(d.b)) return false;
  colour = glm::clamp(Rgb(d.r, d.g, d.b), Rgb(0), Rgb(1));
  return true;
}

// Flattens the node hierarchy into one vertex list (welded by exact position across meshes, as one
// OBJ file shares its 'v' statements among its groups) and convex planar polygons.
class Flattener {
 public:
  Flattener(const aiScene& s, const MeshFaces& mf, const std::string& file, const ModelOptions& o, ModelMesh& out)
      : s_(s), mf_(mf), file_(file), out_(out) {
    // y up: (x, y, z) -> (x, -z, y), a rotation of +90 degrees about x.
    if (o.y_up) up_ = glm::dmat4(1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1);
  }

  void run() {
    // Depth first, parents before children, with an explicit stack: a file may nest nodes deeply.
    std::vector<std::pair<const aiNode*, glm::dmat4>> stack{{s_.mRootNode, up_}};
    while (!stack.empty()) {
      auto [node, parent] = stack.back();
      stack.pop_back();
      const glm::dmat4 t = parent * to_glm(node->mTransformation);
      for (unsigned k = 0; k < node->mNumMeshes; ++k) mesh(node->mMeshes[k], t);
      for (unsigned c = node->mNumChildren; c-- > 0;) stack.emplace_back(node->mChildren[c], t);
    }
  }

 private:
  void mesh(std::uint32_t mi, const glm::dmat4& t) {
    const aiMesh& m = *s_.mMeshes[mi];
    mesh_ = mi;
    ModelFace proto;
    proto.has_colour = material_colour(s_, m, proto.colour);
    proto.place.mesh = mi;
    // A mirroring transform (negative determinant) turns the winding: reverse it back.
    const bool mirrored = glm::determinant(glm::dmat3(t)) < 0;
    std::vector<std::int64_t> welded(m.mNumVertices, -1);
    const Faces& faces = mf_.faces[mi];
    for (std::size_t f = 0; f < faces.size(); ++f) {
      proto.place.face = std::uint32_t(f);
      if (faces[f].size() < 3) {
        ++out_.summary.other_primitives;
        continue;
      }
      if (mf_.split[mi].empty() || mf_.split[mi][f].empty()) {
        polygon(m, t, faces[f], mirrored, welded, proto);
        continue;
      }
      for (const Triangle& tri : mf_.split[mi][f]) {
        polygon(m, t, {tri.begin(), tri.end()}, mirrored, welded, proto);
        ++out_.summary.triangles;
      }
    }
  }

  std::uint32_t vertex(const aiMesh& m, const glm::dmat4& t, std::uint32_t i, std::vector<std::int64_t>& welded) {
    if (welded[i] >= 0) return std::uint32_t(welded[i]);
    const aiVector3D& p = m.mVertices[i];
    const glm::dvec3 v = glm::dvec3(t * glm::dvec4(p.x, p.y, p.z, 1));
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
      const std::string face = place(s_, mesh_, 0);
      throw InputError(file_, face.substr(0, face.rfind(" face ")) + " vertex " + std::to_string(i),
                       "coordinate is not a finite number");
    }
    const auto [it, inserted] = weld_.try_emplace({v.x, v.y, v.z}, std::uint32_t(out_.vertices.size()));
    if (inserted) out_.vertices.push_back(v);
    welded[i] = it->second;
    return it->second;
  }

  void polygon(const aiMesh& m, const glm::dmat4& t, std::vector<std::uint32_t> corners, bool mirrored,
               std::vector<std::int64_t>& welded, const ModelFace& proto) {
    if (mirrored) std::reverse(corners.begin(), corners.end());
    ModelFace face = proto;
    std::vector<glm::dvec3> pts;
    for (auto i : corners) {
      face.indices.push_back(vertex(m, t, i, welded));
      pts.push_back(out_.vertices[face.indices.back()]);
    }
    const std::string rule = check_convex_planar(pts);
    if (rule.rfind("polygon is degenerate", 0) == 0) {
      // Exported models often carry zero-area faces; they cover nothing, so they are skipped (and
      // counted) rather than rejected.
      ++out_.summary.degenerate_faces;
      return;
    }
    if (!rule.empty()) throw InputError(file_, place(s_, proto.place.mesh, proto.place.face), rule);
    if (out_.faces.size() >= kMaxModelPolygons)
      throw InputError(file_, "", "the model has more than " + std::to_string(kMaxModelPolygons) + " polygons");
    out_.faces.push_back(std::move(face));
  }

  const aiScene& s_;
  const MeshFaces& mf_;
  const std::string& file_;
  ModelMesh& out_;
  glm::dmat4 up_{1.0};
  std::uint32_t mesh_ = 0;
  std::map<std::array<double, 3>, std::uint32_t> weld_;
};

ModelMesh flatten(Assimp::Importer& im, const CheckedIOSystem& io, const std::string& file,
                  const ModelOptions& options) {
  if (!im.GetScene()) import_failed(file, im, io);
  if (!io.refusal().empty()) import_failed(file, im, io);
  ModelMesh out;
  const MeshFaces mf = triangulate(im, io, file, options, out.summary);
  const aiScene& s = *im.GetScene();
  if (!s.mRootNode) throw InputError(file, "", "the model has no node hierarchy");
  for (unsigned mi = 0; mi < s.mNumMeshes; ++mi) out.mesh_names.emplace_back(s.mMeshes[mi]->mName.C_Str());
  out.summary.meshes = s.mNumMeshes;
  for (const Faces& f : mf.faces) out.summary.faces += f.size();
  Flattener(s, mf, file, options, out).run();
  if (out.faces.empty())
    throw InputError(file, "",
                     "model has no faces to draw (" + std::to_string(out.summary.faces) + " faces in " +
                         std::to_string(s.mNumMeshes) + " meshes: " + std::to_string(out.summary.degenerate_faces) +
                         " of zero area, " + std::to_string(out.summary.other_primitives) + " points or lines)");
  return out;
}

// In this process: assimp's import and the flattening. Only the isolated child runs these.
ModelMesh load_in_process(const std::string& file, const ModelOptions& options) {
  Assimp::Importer im;
  configure(im);
  auto* io = new CheckedIOSystem(options.max_bytes, true);
  im.SetIOHandler(io);  // the importer owns it
  if (is_obj(file)) io->strip_bom(file);
  im.ReadFile(file, aiProcess_ValidateDataStructure);
  return flatten(im, *io, file, options);
}

ModelMesh parse_in_process(const void* data, std::size_t size, const std::string& format_hint, const std::string& file,
                           const ModelOptions& options) {
  Assimp::Importer im;
  configure(im);
  auto* io = new CheckedIOSystem(options.max_bytes, false);
  im.SetIOHandler(io);
  const bool bom = format_hint == "obj" && size >= 3 && std::memcmp(data, kBom, 3) == 0;
  const std::size_t skip = bom ? 3 : 0;
  im.ReadFileFromMemory(static_cast<const char*>(data) + skip, size - skip, aiProcess_ValidateDataStructure,
                        format_hint.c_str());
  return flatten(im, *io, file, options);
}

// The child's answer through the pipe (common/byte_record.hpp): 'M' and the flattened model, or
// 'E', the place, a NUL and the rule of the InputError it threw.
template <class T>
T take(ByteReader& r) {
  T v{};
  if (!r.pod(v)) throw std::runtime_error("truncated model record");
  return v;
}

std::uint64_t take_count(ByteReader& r, std::size_t each) {
  std::uint64_t n = 0;
  if (!r.count(n, each)) throw std::runtime_error("corrupt model record");
  return n;
}

std::string serialize(const ModelMesh& m) {
  ByteWriter w;
  w.bytes = "M";
  w.pod(std::uint64_t(m.vertices.size()));
  for (const glm::dvec3& v : m.vertices) w.pod(v);
  w.pod(std::uint64_t(m.faces.size()));
  for (const ModelFace& f : m.faces) {
    w.pod(std::uint64_t(f.indices.size()));
    for (auto i : f.indices) w.pod(i);
    w.pod(char(f.has_colour));
    w.pod(f.colour);
    w.pod(f.place);
  }
  w.pod(std::uint64_t(m.mesh_names.size()));
  for (const std::string& n : m.mesh_names) w.str(n);
  w.pod(m.summary);
  return w.bytes;
}

ModelMesh deserialize(const std::string& bytes) {
  ByteReader r(bytes, 1);  // after the tag
  ModelMesh m;
  m.vertices.resize(take_count(r, sizeof(glm::dvec3)));
  for (glm::dvec3& v : m.vertices) v = take<glm::dvec3>(r);
  m.faces.resize(take_count(r, 8));
  for (ModelFace& f : m.faces) {
    f.indices.resize(take_count(r, sizeof(std::uint32_t)));
    for (auto& i : f.indices) i = take<std::uint32_t>(r);
    f.has_colour = take<char>(r) != 0;
    f.colour = take<Rgb>(r);
    f.place = take<ModelFaceRef>(r);
  }
  m.mesh_names.resize(take_count(r, 8));
  for (std::string& n : m.mesh_names)
    if (!r.str(n)) throw std::runtime_error("corrupt model record");
  m.summary = take<ModelSummary>(r);
  return m;
}

// assimp runs in a child process (common/isolated_call): a crash, a hang or a runaway allocation
// inside an importer becomes an InputError naming the file, not the end of the run.
ModelMesh isolated(const std::string& file, const ModelOptions& options, const std::function<ModelMesh()>& load) {
  IsolationLimits limits;
  limits.seconds = options.seconds;
  const IsolatedResult r = run_isolated(
      [&] {
        try {
          return serialize(load());
        } catch (const InputError& e) { return "E" + e.where() + '\0' + e.rule(); }
      },
      limits);
  if (!r.ok && r.reason == "threw") throw InputError(file, "", "the model reader failed: " + r.bytes);
  if (!r.ok) throw InputError(file, "", "assimp " + r.reason + " reading the model; the file is refused");
  if (r.bytes.empty() || r.bytes[0] != 'E') return deserialize(r.bytes);
  const std::size_t nul = r.bytes.find('\0');
  throw InputError(file, r.bytes.substr(1, nul - 1), r.bytes.substr(nul + 1));
}

}  // namespace

ModelMesh load_model(const std::string& file, const ModelOptions& options) {
  check_input_file(file, options.max_bytes, "--max-model-mb");
  return isolated(file, options, [&] { return load_in_process(file, options); });
}

ModelMesh parse_model(const void* data, std::size_t size, const std::string& format_hint, const std::string& file,
                      const ModelOptions& options) {
  if ((long long)size > options.max_bytes)
    throw InputError(file, "", "the model is " + std::to_string(size) + " bytes, more than the limit");
  return isolated(file, options, [&] { return parse_in_process(data, size, format_hint, file, options); });
}

}  // namespace cig
