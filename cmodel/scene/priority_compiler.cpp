#include "scene/priority_compiler.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <utility>

#include <unistd.h>
#include <glm/geometric.hpp>

#include "common/byte_record.hpp"
#include "common/timing.hpp"
#include "scene/polygon_checks.hpp"

namespace cig {

namespace {

// Changes whenever the compiler's output for the same input would change: cached trees of an
// older compiler are not read.
constexpr std::uint64_t kCompilerVersion = 3;
// Beyond this many polygons the O(n^2) pair test is not run: the subobject is compiled (a tree of
// a part whose order was valid splits nothing, it only reorders).
constexpr std::size_t kPairTestLimit = 2048;
// Candidate partition planes tried per node (spread evenly over the node's polygons): the one of
// least 8 splits + |front - back| is taken. Measured on the bison (OBJ/WusonOBJ.obj, 3,732
// triangles): 8 candidates grow it to 2.34x, 32 to 2.07x for 1.2x the compile time; weighting
// splits more (32, 128) grows it more (unbalanced trees split more further down).
constexpr std::size_t kCandidates = 32;
// Sets of up to this many polygons are ordered by the components of their "may hide" graph
// (O(n^2) pair tests and edges): only the polygons of a cycle are split, and only by the planes
// of that cycle. Larger sets are partitioned whole first.
constexpr std::size_t kGraphLimit = 512;

struct Plane {
  glm::dvec3 n{0, 0, 1};
  double d = 0;
  double distance(const glm::dvec3& p) const { return glm::dot(n, p) - d; }
};

Plane plane_of(const std::vector<glm::dvec3>& v, const Polygon& p) {
  std::vector<glm::dvec3> pts;
  glm::dvec3 c(0);
  for (auto i : p.indices) {
    pts.push_back(v[i]);
    c += v[i] / double(p.indices.size());
  }
  const glm::dvec3 n = newell_normal(pts);
  const double len = glm::length(n);
  Plane pl;
  if (len > 0) pl.n = n / len;
  pl.d = glm::dot(pl.n, c);
  return pl;
}

// Points within this distance of a plane lie on it: a millionth of the subobject's size, above the
// rounding of model files (assimp reads single precision: 6e-8 relative) and far below a pixel at
// any distance the part is seen from, so coplanar polygons of a model classify as "on".
double on_tolerance(const std::vector<glm::dvec3>& v) {
  glm::dvec3 lo(0), hi(0);
  if (!v.empty()) lo = hi = v[0];
  for (const auto& p : v) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return 1e-6 * std::max(1e-3, glm::length(hi - lo));
}

enum Side { kOn = 0, kFront = 1, kBack = 2, kSpanning = 3 };

int classify(const Plane& pl, const std::vector<glm::dvec3>& v, const Polygon& p, double eps) {
  int side = kOn;
  for (auto i : p.indices) {
    const double d = pl.distance(v[i]);
    if (d > eps) side |= kFront;
    else if (d < -eps) side |= kBack;
  }
  return side;
}

// The subobject's working state while its tree is built: the polygons (pieces appended), the
// vertices (split points appended, welded by exact position) and each polygon's model face.
struct Work {
  std::vector<glm::dvec3> vertices;
  std::vector<Polygon> polygons;
  std::vector<ModelFaceRef> faces;                                              // empty for inline geometry
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> edge_point;  // edge cut by this plane -> vertex
  std::size_t splits = 0, slivers = 0;
  double eps = 0;
};

// The point where edge (a, b) meets the plane, computed from the edge's ends in a fixed order so
// that the two faces sharing the edge get one vertex (no crack along it).
std::uint32_t edge_point(Work& w, const Plane& pl, std::uint32_t a, std::uint32_t b) {
  const auto key = std::minmax(a, b);
  const auto it = w.edge_point.find(key);
  if (it != w.edge_point.end()) return it->second;
  const glm::dvec3 p = w.vertices[key.first], q = w.vertices[key.second];
  const double dp = pl.distance(p), dq = pl.distance(q);
  const double t = dp / (dp - dq);
  w.vertices.push_back(p + (q - p) * t);
  return w.edge_point[key] = std::uint32_t(w.vertices.size() - 1);
}

double self_at(const Polygon& p, std::size_t k, std::size_t k2, const Work& w, std::uint32_t point) {
  const glm::dvec3 a = w.vertices[p.indices[k]], b = w.vertices[p.indices[k2]];
  const double len = glm::length(b - a);
  const double t = len > 0 ? glm::length(w.vertices[point] - a) / len : 0;
  return p.self_intensity[k] + (p.self_intensity[k2] - p.self_intensity[k]) * t;
}

// A piece of a split polygon, cut in two along a diagonal when the split gave it more corners
// than the pipeline takes (a convex polygon's piece has at most one corner more).
void add_piece(Work& w, const Polygon& proto, std::size_t face, Polygon piece, std::vector<std::uint32_t>& out) {
  std::vector<glm::dvec3> pts;
  for (auto i : piece.indices) pts.push_back(w.vertices[i]);
  if (piece.indices.size() < 3 || !(glm::length(newell_normal(pts)) > w.eps * w.eps)) {
    ++w.slivers;  // a piece of no area covers nothing
    return;
  }
  if (piece.indices.size() > std::size_t(kMaxSceneVertices)) {
    const std::size_t half = piece.indices.size() / 2;
    Polygon a = piece, b = piece;
    a.indices.assign(piece.indices.begin(), piece.indices.begin() + std::ptrdiff_t(half) + 1);
    b.indices.assign(piece.indices.begin() + std::ptrdiff_t(half), piece.indices.end());
    b.indices.push_back(piece.indices[0]);
    if (proto.self_lit) {
      a.self_intensity.assign(piece.self_intensity.begin(), piece.self_intensity.begin() + std::ptrdiff_t(half) + 1);
      b.self_intensity.assign(piece.self_intensity.begin() + std::ptrdiff_t(half), piece.self_intensity.end());
      b.self_intensity.push_back(piece.self_intensity[0]);
    }
    add_piece(w, proto, face, std::move(a), out);
    add_piece(w, proto, face, std::move(b), out);
    return;
  }
  w.polygons.push_back(std::move(piece));
  if (!w.faces.empty()) {
    const ModelFaceRef ref = w.faces[face];
    w.faces.push_back(ref);
  }
  out.push_back(std::uint32_t(w.polygons.size() - 1));
}

// Splits polygon `pi` by the plane into its front and back pieces.
void split(Work& w, const Plane& pl, std::uint32_t pi, std::vector<std::uint32_t>& front,
           std::vector<std::uint32_t>& back) {
  const Polygon p = w.polygons[pi];  // a copy: add_piece grows w.polygons
  Polygon f = p, b = p;
  f.indices.clear();
  b.indices.clear();
  f.self_intensity.clear();
  b.self_intensity.clear();
  const std::size_t n = p.indices.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t k2 = (k + 1) % n;
    const std::uint32_t a = p.indices[k], c = p.indices[k2];
    const double da = pl.distance(w.vertices[a]), dc = pl.distance(w.vertices[c]);
    const int sa = da > w.eps ? kFront : da < -w.eps ? kBack : kOn;
    const int sc = dc > w.eps ? kFront : dc < -w.eps ? kBack : kOn;
    if (sa != kBack) {
      f.indices.push_back(a);
      if (p.self_lit) f.self_intensity.push_back(p.self_intensity[k]);
    }
    if (sa != kFront) {
      b.indices.push_back(a);
      if (p.self_lit) b.self_intensity.push_back(p.self_intensity[k]);
    }
    if ((sa | sc) == kSpanning) {
      const std::uint32_t x = edge_point(w, pl, a, c);
      f.indices.push_back(x);
      b.indices.push_back(x);
      if (p.self_lit) {
        f.self_intensity.push_back(self_at(p, k, k2, w, x));
        b.self_intensity.push_back(f.self_intensity.back());
      }
    }
  }
  ++w.splits;
  add_piece(w, p, pi, std::move(f), front);
  add_piece(w, p, pi, std::move(b), back);
}

// j may hide i from some eye unless j lies wholly behind-or-on i's plane or i wholly
// in-front-or-on j's (the pair test of priority_compiler.hpp).
bool may_hide(const Work& w, const std::vector<Plane>& planes, std::size_t a, std::size_t b,
              const std::vector<std::uint32_t>& polys) {
  if ((classify(planes[b], w.vertices, w.polygons[polys[a]], w.eps) & kFront) == 0) return false;
  return (classify(planes[a], w.vertices, w.polygons[polys[b]], w.eps) & kBack) != 0;
}

// The "may hide" graph over a set (positions 0..m-1 of `polys`): an edge a -> b when a must be
// drawn before b. Coplanar polygons facing the same way cannot hide each other, but a decal must
// stay before the surface it lies on, so they keep the list's order (an edge from the earlier).
std::vector<std::vector<std::uint32_t>> hide_graph(const Work& w, const std::vector<std::uint32_t>& polys) {
  const std::size_t m = polys.size();
  std::vector<Plane> planes;
  for (auto q : polys) planes.push_back(plane_of(w.vertices, w.polygons[q]));
  std::vector<std::vector<std::uint32_t>> out(m);
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t b = a + 1; b < m; ++b) {
      const bool ab = may_hide(w, planes, a, b, polys), ba = may_hide(w, planes, b, a, polys);
      if (ab) out[a].push_back(std::uint32_t(b));
      if (ba) out[b].push_back(std::uint32_t(a));
      if (!ab && !ba && glm::dot(planes[a].n, planes[b].n) > 0 &&
          classify(planes[a], w.vertices, w.polygons[polys[b]], w.eps) == kOn)
        out[a].push_back(std::uint32_t(b));
    }
  return out;
}

// Tarjan's strongly connected components, without recursion: comp[v] for every vertex.
std::vector<std::uint32_t> components(const std::vector<std::vector<std::uint32_t>>& g, std::uint32_t& count) {
  const std::uint32_t m = std::uint32_t(g.size()), unset = ~0u;
  std::vector<std::uint32_t> index(m, unset), low(m, 0), comp(m, unset), stack;
  std::vector<std::pair<std::uint32_t, std::size_t>> call;  // (vertex, next edge)
  std::uint32_t next = 0;
  count = 0;
  for (std::uint32_t root = 0; root < m; ++root) {
    if (index[root] != unset) continue;
    call.push_back({root, 0});
    index[root] = low[root] = next++;
    stack.push_back(root);
    while (!call.empty()) {
      auto& [v, e] = call.back();
      if (e < g[v].size()) {
        const std::uint32_t u = g[v][e++];
        if (index[u] == unset) {
          index[u] = low[u] = next++;
          stack.push_back(u);
          call.push_back({u, 0});
        } else if (comp[u] == unset) {
          low[v] = std::min(low[v], index[u]);
        }
        continue;
      }
      const std::uint32_t done = v;
      call.pop_back();
      if (!call.empty()) low[call.back().first] = std::min(low[call.back().first], low[done]);
      if (low[done] != index[done]) continue;
      for (std::uint32_t u = unset; u != done;) {
        u = stack.back();
        stack.pop_back();
        comp[u] = count;
      }
      ++count;
    }
  }
  return comp;
}

// The set's strongly connected components of "may hide", in a visibility order: a component
// before every one its members may hide (ties to the one listed first, so a set already in a
// valid order keeps it), members in list order. A component of one polygon needs no split; one
// of several is a cycle that only a partition plane breaks.
std::vector<std::vector<std::uint32_t>> ordered_components(const Work& w, const std::vector<std::uint32_t>& polys) {
  const auto g = hide_graph(w, polys);
  std::uint32_t count = 0;
  const std::vector<std::uint32_t> comp = components(g, count);
  std::vector<std::vector<std::uint32_t>> members(count), after(count);
  std::vector<std::uint32_t> waiting(count, 0);
  for (std::uint32_t v = 0; v < g.size(); ++v) {
    members[comp[v]].push_back(v);
    for (auto u : g[v])
      if (comp[u] != comp[v]) after[comp[v]].push_back(comp[u]), ++waiting[comp[u]];
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ready;  // (first member, component), a min-heap
  for (std::uint32_t c = 0; c < count; ++c)
    if (waiting[c] == 0) ready.push_back({members[c][0], c});
  std::make_heap(ready.begin(), ready.end(), std::greater<>());
  std::vector<std::vector<std::uint32_t>> order;
  while (!ready.empty()) {
    std::pop_heap(ready.begin(), ready.end(), std::greater<>());
    const std::uint32_t c = ready.back().second;
    ready.pop_back();
    order.emplace_back();
    for (auto v : members[c]) order.back().push_back(polys[v]);
    for (auto d : after[c])
      if (--waiting[d] == 0) {
        ready.push_back({members[d][0], d});
        std::push_heap(ready.begin(), ready.end(), std::greater<>());
      }
  }
  return order;
}

struct Partition {
  std::vector<std::uint32_t> on, front, back;
};

// The candidate plane with the fewest splits, then the best balance, among kCandidates polygons
// spread over the node's list.
std::pair<Plane, std::uint32_t> choose_plane(const Work& w, const std::vector<std::uint32_t>& polys) {
  const std::size_t m = polys.size(), k = std::min(m, kCandidates);
  Plane best;
  std::uint32_t best_polygon = polys[0];
  long long best_score = -1;
  for (std::size_t c = 0; c < k; ++c) {
    const std::uint32_t cand = polys[c * m / k];
    const Plane pl = plane_of(w.vertices, w.polygons[cand]);
    long long splits = 0, front = 0, back = 0;
    for (auto q : polys) {
      const int side = classify(pl, w.vertices, w.polygons[q], w.eps);
      splits += side == kSpanning;
      front += side == kFront;
      back += side == kBack;
    }
    const long long score = 8 * splits + std::llabs(front - back);
    if (best_score < 0 || score < best_score) {
      best_score = score;
      best = pl;
      best_polygon = cand;
    }
  }
  return {best, best_polygon};
}

// The splitter itself lies on its plane whatever its planarity noise (the loaders admit 1e-4 of
// its diameter), so every node takes at least one polygon and the build ends.
Partition partition(Work& w, const Plane& pl, std::uint32_t splitter, const std::vector<std::uint32_t>& polys) {
  Partition part;
  w.edge_point.clear();  // split points are shared within one plane's cut only
  for (auto q : polys) {
    const int side = q == splitter ? kOn : classify(pl, w.vertices, w.polygons[q], w.eps);
    if (side == kOn) part.on.push_back(q);
    else if (side == kFront) part.front.push_back(q);
    else if (side == kBack) part.back.push_back(q);
    else split(w, pl, q, part.front, part.back);
  }
  return part;
}

struct BuildNode {
  std::vector<std::uint32_t> on;
  Plane plane;
  std::int32_t front = -1, back = -1, next = -1;
  bool run = false;  // polygons in an order valid from every eye, no plane
};

// Where a chain of nodes hangs: a node's front or back subtree, or the root (node -1).
struct Task {
  std::vector<std::uint32_t> polys;
  std::int32_t parent = -1;
  bool front = false;
};

// One set as a chain of nodes in visibility order: runs of polygons that need no split (leaves)
// and, for each cycle of "may hide", a partition node whose two sides become further tasks.
// Sets beyond kGraphLimit polygons skip the O(n^2) graph and are partitioned whole.
void build_chain(Work& w, Task& t, std::vector<BuildNode>& nodes, std::vector<Task>& tasks) {
  std::vector<std::vector<std::uint32_t>> comps;
  if (t.polys.size() <= kGraphLimit) comps = ordered_components(w, t.polys);
  else comps.push_back(std::move(t.polys));
  std::int32_t last = -1;
  auto link = [&](std::int32_t k) {
    if (last >= 0) nodes[std::size_t(last)].next = k;
    else if (t.parent >= 0) (t.front ? nodes[std::size_t(t.parent)].front : nodes[std::size_t(t.parent)].back) = k;
    last = k;
  };
  for (std::size_t c = 0; c < comps.size(); ++c) {
    const bool cycle = comps[c].size() > 1;
    if (!cycle && last >= 0 && nodes[std::size_t(last)].run) {
      nodes[std::size_t(last)].on.push_back(comps[c][0]);  // extends the open run
      continue;
    }
    const std::int32_t k = std::int32_t(nodes.size());
    nodes.emplace_back();
    link(k);
    if (!cycle) {
      nodes[std::size_t(k)].on = comps[c];
      nodes[std::size_t(k)].run = true;
      continue;
    }
    const auto [pl, splitter] = choose_plane(w, comps[c]);
    Partition part = partition(w, pl, splitter, comps[c]);
    nodes[std::size_t(k)].plane = pl;
    nodes[std::size_t(k)].on = std::move(part.on);
    if (!part.front.empty()) tasks.push_back({std::move(part.front), k, true});
    if (!part.back.empty()) tasks.push_back({std::move(part.back), k, false});
  }
}

// The whole tree, built without recursion (a tree over a mesh can be as deep as the mesh is
// long); false when splitting grows the subobject beyond the limit.
bool build_tree(Work& w, std::size_t limit, std::vector<BuildNode>& nodes) {
  Task root;
  for (std::uint32_t i = 0; i < w.polygons.size(); ++i) root.polys.push_back(i);
  std::vector<Task> tasks{std::move(root)};
  nodes.clear();
  while (!tasks.empty()) {
    Task t = std::move(tasks.back());
    tasks.pop_back();
    build_chain(w, t, nodes, tasks);
    if (w.polygons.size() > limit) return false;
  }
  return true;
}

// The subobject rebuilt from the tree: each node's polygons one after another in the modeller's
// order (decals on one plane keep theirs), the node's plane that of its first polygon (children
// swapped when that polygon faces the other way).
void emit(const Work& w, const std::vector<BuildNode>& nodes, Subobject& s) {
  s.vertices = w.vertices;
  s.polygons.clear();
  std::vector<ModelFaceRef> faces;
  s.bsp.assign(nodes.size(), BspNode{});
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    BspNode& b = s.bsp[k];
    b.first = std::uint32_t(s.polygons.size());
    b.count = std::uint32_t(nodes[k].on.size());
    b.front = nodes[k].front;
    b.back = nodes[k].back;
    b.next = nodes[k].next;
    for (auto q : nodes[k].on) {
      s.polygons.push_back(w.polygons[q]);
      if (!w.faces.empty()) faces.push_back(w.faces[q]);
    }
    if (!nodes[k].run && glm::dot(plane_of(w.vertices, w.polygons[nodes[k].on[0]]).n, nodes[k].plane.n) < 0)
      std::swap(b.front, b.back);
  }
  s.model_faces = std::move(faces);
}

// ---- The cache: one file per compiled subobject, named by the hash of what the compiler read
// (records of common/byte_record.hpp).

std::uint64_t fnv1a(const std::string& bytes, std::uint64_t h = 1469598103934665603ull) {
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  return h;
}

void put_polygons(ByteWriter& out, const std::vector<glm::dvec3>& vertices, const std::vector<Polygon>& polygons) {
  out.pod(std::uint64_t(vertices.size()));
  for (const auto& v : vertices) out.pod(v);
  out.pod(std::uint64_t(polygons.size()));
  for (const Polygon& p : polygons) {
    out.pod(std::uint64_t(p.indices.size()));
    for (auto i : p.indices) out.pod(i);
    out.pod(p.colour);
    out.pod(char(p.opaque | p.protect << 1 | p.self_lit << 2));
    for (double x : p.self_intensity) out.pod(x);
  }
}

// What the compiler reads of a subobject, with its version and setting: the cache key.
std::uint64_t content_key(const Subobject& s, const PriorityCompilerOptions& o) {
  ByteWriter in;
  in.pod(kCompilerVersion);
  in.pod(o.max_growth);
  in.pod(std::uint64_t(o.split_allowance));
  put_polygons(in, s.vertices, s.polygons);
  return fnv1a(in.bytes);
}

std::string payload(const Subobject& s, std::size_t splits, std::size_t slivers) {
  ByteWriter out;
  put_polygons(out, s.vertices, s.polygons);
  out.pod(std::uint64_t(s.model_faces.size()));
  for (const auto& f : s.model_faces) out.pod(f);
  out.pod(std::uint64_t(s.bsp.size()));
  for (const auto& n : s.bsp) out.pod(n);
  out.pod(std::uint64_t(splits));
  out.pod(std::uint64_t(slivers));
  return out.bytes;
}

bool get_polygons(ByteReader& c, Subobject& s) {
  std::uint64_t n = 0;
  if (!c.count(n, sizeof(glm::dvec3))) return false;
  s.vertices.resize(n);
  for (auto& v : s.vertices)
    if (!c.pod(v)) return false;
  if (!c.count(n, 8)) return false;
  s.polygons.assign(n, Polygon{});
  for (Polygon& p : s.polygons) {
    std::uint64_t k = 0;
    char flags = 0;
    if (!c.count(k, 4) || k < 3 || k > std::uint64_t(kMaxSceneVertices)) return false;
    p.indices.resize(k);
    for (auto& i : p.indices)
      if (!c.pod(i) || i >= s.vertices.size()) return false;
    if (!c.pod(p.colour) || !c.pod(flags)) return false;
    p.opaque = flags & 1;
    p.protect = flags & 2;
    p.self_lit = flags & 4;
    p.self_intensity.resize(p.self_lit ? k : 0);
    for (double& x : p.self_intensity)
      if (!c.pod(x)) return false;
  }
  return true;
}

// A cached subobject, every index checked (a damaged or foreign file is recompiled, not trusted).
bool read_compiled(const std::string& bytes, Subobject& s, std::size_t& splits, std::size_t& slivers) {
  ByteReader c(bytes);
  std::uint64_t n = 0, a = 0, b = 0;
  if (!get_polygons(c, s) || !c.count(n, sizeof(ModelFaceRef))) return false;
  s.model_faces.resize(n);
  for (auto& f : s.model_faces)
    if (!c.pod(f)) return false;
  if (!c.count(n, sizeof(BspNode)) || (!s.model_faces.empty() && s.model_faces.size() != s.polygons.size()))
    return false;
  s.bsp.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    BspNode& node = s.bsp[k];
    if (!c.pod(node) || node.count == 0 || node.first > s.polygons.size() ||
        node.count > s.polygons.size() - node.first)
      return false;
    for (std::int32_t child : {node.front, node.back, node.next})  // children come later: no cycle
      if (child != -1 && (child <= std::int32_t(k) || child >= std::int32_t(n))) return false;
  }
  if (!c.pod(a) || !c.pod(b) || !c.done()) return false;
  splits = a;
  slivers = b;
  return true;
}

constexpr char kMagic[8] = {'C', 'I', 'G', 'B', 'S', 'P', '1', '\n'};

std::string cache_path(const std::string& dir, std::uint64_t key) {
  char name[32];
  std::snprintf(name, sizeof name, "%016llx.bsp", static_cast<unsigned long long>(key));
  return dir + "/" + name;
}

bool load_cached(const std::string& file, std::uint64_t key, Subobject& s, std::size_t& splits, std::size_t& slivers) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return false;
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::uint64_t file_key = 0, sum = 0;
  if (bytes.size() < 24 || std::memcmp(bytes.data(), kMagic, 8) != 0) return false;
  std::memcpy(&file_key, bytes.data() + 8, 8);
  std::memcpy(&sum, bytes.data() + 16, 8);
  const std::string body = bytes.substr(24);
  if (file_key != key || sum != fnv1a(body)) return false;
  Subobject copy = s;
  if (!read_compiled(body, copy, splits, slivers)) return false;
  s = std::move(copy);
  return true;
}

// Written to a temporary name and renamed, so a reader never sees half a file and two runs
// writing the same key leave one whole file. Failures only cost the next load its speed.
bool store(const std::string& dir, std::uint64_t key, const std::string& body) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  const std::string file = cache_path(dir, key);
  const std::string tmp = file + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) return false;
    const std::uint64_t sum = fnv1a(body);
    out.write(kMagic, 8);
    out.write(reinterpret_cast<const char*>(&key), 8);
    out.write(reinterpret_cast<const char*>(&sum), 8);
    out.write(body.data(), std::streamsize(body.size()));
    if (!out) return false;
  }
  std::filesystem::rename(tmp, file, ec);
  if (ec) std::filesystem::remove(tmp, ec);
  return !ec;
}

// One subobject: its tree from the cache or the compiler; false when splitting grew too much.
bool compile_subobject(Subobject& s, const PriorityCompilerOptions& o, PriorityCompileSummary& sum) {
  const std::size_t before = s.polygons.size();
  std::uint64_t key = 0;
  std::size_t splits = 0, slivers = 0;
  if (!o.cache_dir.empty()) {
    key = content_key(s, o);
    if (load_cached(cache_path(o.cache_dir, key), key, s, splits, slivers)) ++sum.cache_hits;
  }
  if (s.bsp.empty()) {
    Work w{s.vertices, s.polygons, s.model_faces, {}, 0, 0, on_tolerance(s.vertices)};
    std::vector<BuildNode> nodes;
    const std::size_t limit = std::size_t(o.max_growth * double(before)) + o.split_allowance;
    if (!build_tree(w, limit, nodes)) return false;
    emit(w, nodes, s);
    splits = w.splits;
    slivers = w.slivers;
    if (!o.cache_dir.empty() && store(o.cache_dir, key, payload(s, splits, slivers))) ++sum.cache_writes;
  }
  sum.polygons_before += before;
  sum.polygons_after += s.polygons.size();
  sum.splits += splits;
  sum.slivers_dropped += slivers;
  sum.nodes += s.bsp.size();
  return true;
}

// ---- Occlusion groups of models: one tree over the group.

struct Placed {
  glm::dvec3 centre;
  double radius;
  glm::dmat3 rot;
};

Placed placed(const Object& o) {
  const glm::dmat3 rot = body_to_world(o.pose.heading_deg, o.pose.pitch_deg, o.pose.roll_deg);
  return {rot * o.sphere_centre + o.pose.position, o.sphere_radius, rot};
}

bool has_tree_subobject(const Object& o) {
  return !o.polyhedron &&
         std::any_of(o.subobjects.begin(), o.subobjects.end(), [](const Subobject& s) { return s.priority_tree; });
}

std::size_t find_root(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// The group's objects as one object at the first one's position: every subobject's polygons in
// one subobject (each member's vertices kept apart, so Gouraud normals average as before), light
// points placed alike. The first member's crease angle serves all (counted when they differ).
Object merge_group(const Scene& scene, const std::vector<std::size_t>& members, PriorityCompileSummary& sum) {
  const Object& first = scene.objects[members[0]];
  Object g;
  g.layer = first.layer;
  g.pose.position = first.pose.position;
  Subobject merged;
  merged.name = "group";
  merged.priority_tree = true;
  merged.crease_angle_deg = first.subobjects[0].crease_angle_deg;
  for (std::size_t k = 0; k < members.size(); ++k) {
    const Object& o = scene.objects[members[k]];
    const glm::dmat3 rot = body_to_world(o.pose.heading_deg, o.pose.pitch_deg, o.pose.roll_deg);
    const glm::dvec3 shift = o.pose.position - first.pose.position;
    g.name += (k ? "+" : "") + o.name;
    for (const Subobject& so : o.subobjects) {
      if (so.crease_angle_deg != merged.crease_angle_deg) ++sum.group_crease_changed;
      const std::uint32_t base = std::uint32_t(merged.vertices.size());
      for (const glm::dvec3& v : so.vertices) merged.vertices.push_back(rot * v + shift);
      for (Polygon p : so.polygons) {
        for (auto& i : p.indices) i += base;
        merged.polygons.push_back(std::move(p));
      }
    }
    for (LightPoint l : o.light_points) {
      l.position = rot * l.position + shift;
      if (l.beam) l.beam->frame = rot * l.beam->frame;  // the group has no rotation: the lobe keeps the member's
      g.light_points.push_back(l);
    }
  }
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const glm::dvec3& v : merged.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
  for (const LightPoint& l : g.light_points) lo = glm::min(lo, l.position), hi = glm::max(hi, l.position);
  g.sphere_centre = merged.centre = 0.5 * (lo + hi);
  for (const glm::dvec3& v : merged.vertices)
    g.sphere_radius = std::max(g.sphere_radius, glm::length(v - g.sphere_centre));
  for (const LightPoint& l : g.light_points)
    g.sphere_radius = std::max(g.sphere_radius, glm::length(l.position - g.sphere_centre));
  g.sphere_radius *= 1 + 1e-12;
  g.subobjects.push_back(std::move(merged));
  return g;
}

// Objects of one layer whose bounding spheres overlap, one of them at least a model (a subobject
// with "priority_order": "tree"), interpenetrate or may: seed 000 would make them an occlusion
// group and merge their lists by distance, which orders parts, not polygons. They become one
// object whose polygons get one tree. Groups of inline objects only keep seed 000's merge.
void group_interpenetrating(Scene& scene, PriorityCompileSummary& sum) {
  const std::size_t n = scene.objects.size();
  std::vector<std::size_t> parent(n), models;
  std::vector<Placed> where;
  for (std::size_t i = 0; i < n; ++i) {
    parent[i] = i;
    where.push_back(placed(scene.objects[i]));
    if (has_tree_subobject(scene.objects[i])) models.push_back(i);
  }
  if (models.empty()) return;
  for (std::size_t m : models)
    for (std::size_t j = 0; j < n; ++j) {
      const Object& o = scene.objects[j];
      if (j == m || o.polyhedron || o.subobjects.empty() || o.layer != scene.objects[m].layer) continue;
      if (glm::length(where[m].centre - where[j].centre) < where[m].radius + where[j].radius)
        parent[find_root(parent, m)] = find_root(parent, j);
    }
  std::vector<std::vector<std::size_t>> groups(n);
  for (std::size_t i = 0; i < n; ++i) groups[find_root(parent, i)].push_back(i);
  std::vector<Object> out;
  std::vector<bool> merged(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    const std::vector<std::size_t>& g = groups[find_root(parent, i)];
    if (g.size() < 2) {
      out.push_back(std::move(scene.objects[i]));
    } else if (g[0] == i) {  // the group takes its first member's place in the list
      out.push_back(merge_group(scene, g, sum));
      ++sum.groups;
      sum.grouped_objects += g.size();
    }
  }
  scene.objects = std::move(out);
}

}  // namespace

bool modeller_order_valid(const Subobject& s) {
  const std::size_t n = s.polygons.size();
  if (n > kPairTestLimit) return false;
  const double eps = on_tolerance(s.vertices);
  std::vector<Plane> planes;
  for (const Polygon& p : s.polygons) planes.push_back(plane_of(s.vertices, p));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const int j_side = classify(planes[i], s.vertices, s.polygons[j], eps);  // j against i's plane
      if ((j_side & kFront) == 0) continue;                                    // behind or on i
      const int i_side = classify(planes[j], s.vertices, s.polygons[i], eps);  // i against j's plane
      if ((i_side & kBack) == 0) continue;                                     // in front of or on j
      return false;
    }
  return true;
}

std::string default_priority_cache_dir() {
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::string(x) + "/cig/priority";
  if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.cache/cig/priority";
  return "";
}

namespace {

void add(PriorityCompileSummary& to, const PriorityCompileSummary& s) {
  to.groups += s.groups;
  to.grouped_objects += s.grouped_objects;
  to.group_crease_changed += s.group_crease_changed;
  to.subobjects += s.subobjects;
  to.ordered += s.ordered;
  to.kept_not_valid += s.kept_not_valid;
  to.compiled += s.compiled;
  to.too_large += s.too_large;
  to.polygons_before += s.polygons_before;
  to.polygons_after += s.polygons_after;
  to.splits += s.splits;
  to.nodes += s.nodes;
  to.slivers_dropped += s.slivers_dropped;
  to.cache_hits += s.cache_hits;
  to.cache_writes += s.cache_writes;
}

}  // namespace

PriorityCompileSummary compile_priorities(Scene& scene, const PriorityCompilerOptions& options) {
  PriorityCompileSummary sum;
  if (!options.enabled) return sum;
  const auto t0 = Clock::now();
  group_interpenetrating(scene, sum);
  for (Object& o : scene.objects) {
    if (o.polyhedron) continue;  // convex: any order is a visibility order (stage F's objects)
    for (Subobject& s : o.subobjects) {
      const auto t1 = Clock::now();
      PriorityCompileSummary& one = s.priority;
      one = PriorityCompileSummary{};
      one.subobjects = 1;
      if (modeller_order_valid(s)) ++one.ordered;
      else if (!s.priority_tree) ++one.kept_not_valid;
      else if (compile_subobject(s, options, one)) ++one.compiled;
      else ++one.too_large;
      one.ms = ms_since(t1);
      add(sum, one);
    }
  }
  sum.ms = ms_since(t0);
  return sum;
}

}  // namespace cig
