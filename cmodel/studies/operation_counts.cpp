// The counted model of seed 000's scene manager (operation_counts.hpp). Every increment names the
// step of the seed's pseudo-code it counts. Two sorts of per-step cost:
//   * derived: the arithmetic (C, O, A, M) of B, of the transform, of the visibility test and of the
//     sphere test is performed here operation by operation through Tally, and its count is what the
//     table prints;
//   * the table's lump: the seed prints only each unit's totals of R and L, and the per-point cost
//     of the subobject sorter's decisions; these are charged per step as one figure (the comment
//     says how the unit total is split between steps: that split is this model's, chosen so that
//     every step's count is non-negative and the totals equal the table).
#include "studies/operation_counts.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <queue>
#include <random>
#include <sstream>
#include <stdexcept>

#include <glm/vec2.hpp>

namespace cig {

double cycles(const OperationCounts& c, const OperationCost& k) {
  return double(c.R) * k.R + double(c.C) * k.C + double(c.O) * k.O + double(c.L) * k.L + double(c.A) * k.A +
         double(c.M) * k.M + double(c.D) * k.D;
}

double cycles(const SignedCounts& c, const OperationCost& k) {
  return double(c.R) * k.R + double(c.C) * k.C + double(c.O) * k.O + double(c.L) * k.L + double(c.A) * k.A +
         double(c.M) * k.M + double(c.D) * k.D;
}

namespace {

// ---- Per-step costs that the seed prints only as totals ------------------------------------------
// Preliminary processing unit.
constexpr std::uint64_t kPilotWords = 25;     // R: the pilot's vectors from the host (table: 25)
constexpr std::uint64_t kPilotMemory = 241;   // L: their storage, the sine table and B (table: 241)
constexpr std::uint64_t kObjectWords = 34;    // R: one object's record from the host (table: 34 No)
constexpr std::uint64_t kObjectMemory = 224;  // L: its storage, B, centre and V[i] (table: 224 No)
// Preliminary sorting unit: L = 90 No - 20 split as 70 per object + 20 per sphere test.
constexpr std::uint64_t kSortingWords = 25;  // R: the pilot's frame data (table: 25)
constexpr std::uint64_t kSortWords = 36;     // R: per object (table: 36 No)
constexpr std::uint64_t kSortMemory = 70;    // L: per object: record, key into the sorter, SP out
constexpr std::uint64_t kPairMemory = 20;    // L: per sphere test: SP[i], SP[j], centres, radii, marks
// Subobject sorter. QS[i] of every object: 1 word, then 3 per plane and 7 per point, each exchanged
// with the host (R) and stored (L): the table's No*[Npl*(3 + 7 Np) + 1] in both R and L.
constexpr std::uint64_t kListHeader = 1, kPlaneHeader = 3, kPointWords = 7;
// An occluded object's planes, read again for the distances: R 3 + 10 per point (derived: the
// table's 10 Npl read as 10 Np), L 63 per plane + 58 per point (the table's L less the decisions').
constexpr std::uint64_t kOccludedPlaneWords = 3, kOccludedPointWords = 10;
constexpr std::uint64_t kOccludedPlaneMemory = 63, kOccludedPointMemory = 58;
// One merge decision, per point of the plane it places (the table's per-point factor of C, A, M, D
// and of L's 144; the seed does not itemize it).
constexpr OperationCounts kDecisionPerPoint{0, 2, 0, 144, 27, 48, 9};

// The scene's geometry.
constexpr double kRadius = 10;  // every object's bounding sphere, m
constexpr double kFirstDepth = 5 * kRadius;
constexpr double kChainStep = 0.8 * kRadius;  // occluded chain: neighbours (and next-but-one) overlap
constexpr double kSpacing = 3 * kRadius;      // the others: no two spheres meet
constexpr double kFarPlane = 1e12;            // the far test's depth (every object nearer)

// Counted arithmetic: each call is one operation of its kind.
class Tally {
 public:
  explicit Tally(OperationCounts& c) : c_(c) {}
  double mul(double a, double b) { return ++c_.M, a * b; }
  double add(double a, double b) { return ++c_.A, a + b; }
  double sub(double a, double b) { return ++c_.A, a - b; }
  std::size_t add_index(std::size_t a, std::size_t b) { return ++c_.A, a + b; }
  bool less(double a, double b) { return ++c_.C, a < b; }
  bool test(bool flag) { return ++c_.C, flag; }   // comparison of a flag + conditional jump
  double negate(double a) { return ++c_.O, -a; }  // the sign bit flipped: a logical instruction
  bool both(bool a, bool b) { return ++c_.O, a && b; }
  void logic() { ++c_.O; }
  void host(std::uint64_t words) { c_.R += words; }
  void memory(std::uint64_t accesses) { c_.L += accesses; }
  void charge(const OperationCounts& step, std::uint64_t times) {
    c_.R += step.R * times;
    c_.C += step.C * times;
    c_.O += step.O * times;
    c_.L += step.L * times;
    c_.A += step.A * times;
    c_.M += step.M * times;
    c_.D += step.D * times;
  }

 private:
  OperationCounts& c_;
};

// "calculating the matrix B" from the pilot's heading psi (about y), pitch theta (about x) and roll
// gamma (about z): B = Rz(gamma) Rx(theta) Ry(psi), world -> pilot, row-major:
//   [ cg cp + sg (st sp)   sg ct   sg (st cp) - cg sp ]
//   [ cg (st sp) - sg cp   cg ct   sg sp + cg (st cp) ]
//   [ ct sp                -st     ct cp              ]
// 4 O, 16 M, 4 A: the table's constants O = 4, M = 16, A = 4.
std::array<double, 9> matrix_b(Tally& t, double heading, double pitch, double roll) {
  // Sines and cosines from a table: the angle's bits masked into a table index, one O per angle
  // (the table reads are part of kPilotMemory).
  t.logic();
  const double sp = std::sin(heading), cp = std::cos(heading);
  t.logic();
  const double st = std::sin(pitch), ct = std::cos(pitch);
  t.logic();
  const double sg = std::sin(roll), cg = std::cos(roll);
  std::array<double, 9> b{};
  // The four two-term entries: 1 M + 2 M (the three-factor product formed afresh each time) + 1 A.
  b[0] = t.add(t.mul(cg, cp), t.mul(sg, t.mul(st, sp)));
  b[2] = t.sub(t.mul(sg, t.mul(st, cp)), t.mul(cg, sp));
  b[3] = t.sub(t.mul(cg, t.mul(st, sp)), t.mul(sg, cp));
  b[5] = t.add(t.mul(sg, sp), t.mul(cg, t.mul(st, cp)));
  // The four one-product entries: 1 M each; -st: the sign flipped, 1 O.
  b[1] = t.mul(sg, ct);
  b[4] = t.mul(cg, ct);
  b[6] = t.mul(ct, sp);
  b[8] = t.mul(ct, cp);
  b[7] = t.negate(st);
  return b;
}

// "transforming Po_i into the pilot coordinate system": B times the position relative to the pilot
// (sent so by the host: no subtraction here), 9 M + 6 A.
glm::dvec3 to_pilot(Tally& t, const std::array<double, 9>& b, const glm::dvec3& d) {
  glm::dvec3 e;
  for (int r = 0; r < 3; ++r)
    e[r] = t.add(t.add(t.mul(b[3 * r], d.x), t.mul(b[3 * r + 1], d.y)), t.mul(b[3 * r + 2], d.z));
  return e;
}

}  // namespace

// ---- The scene -----------------------------------------------------------------------------------

namespace {

double plane_depth(double radius, std::uint32_t plane, std::uint32_t planes) {
  return 0.9 * radius * (1.0 - (2.0 * plane + 1.0) / planes);  // plane 0 the farthest
}

glm::dvec2 ring(std::uint32_t point, std::uint32_t points) {
  const double angle = 2.0 * M_PI * point / points;
  return {std::cos(angle), std::sin(angle)};
}

}  // namespace

glm::dvec3 plane_point(const glm::dvec3& centre, double radius, std::uint32_t plane, std::uint32_t planes,
                       std::uint32_t point, std::uint32_t points) {
  const glm::dvec2 r = ring(point, points);
  return centre + glm::dvec3(0.3 * radius * r.x, 0.3 * radius * r.y, plane_depth(radius, plane, planes));
}

CountedScene make_counted_scene(const ManagerStructure& s, std::uint64_t seed) {
  if (s.objects < 1 || s.occluded > s.objects || s.planes < 1 || s.points < 3)
    throw std::invalid_argument("make_counted_scene: needs No >= 1, 0 <= Noc <= No, Npl >= 1, Np >= 3");
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  CountedScene scene;
  scene.structure = s;
  scene.heading = (unit(rng) * 2 - 1) * M_PI;
  scene.pitch = (unit(rng) * 2 - 1) * 0.45 * M_PI;
  scene.roll = (unit(rng) * 2 - 1) * M_PI;
  OperationCounts unused;
  Tally t(unused);
  const std::array<double, 9> b = matrix_b(t, scene.heading, scene.pitch, scene.roll);
  // Pilot coordinates first (x right, y up, z depth), then the host's world-axes offset B^T e.
  const std::size_t n = std::size_t(s.objects);
  std::vector<CountedObject> in_depth(n);
  std::vector<std::uint8_t> occluded_in_depth(n, 0);
  const std::size_t chain = s.occluded >= 2 ? std::size_t(s.occluded) : 0;
  double z = kFirstDepth;
  for (std::size_t k = 0; k < n; ++k) {
    glm::dvec3 e(0, 0, z);
    if (k >= chain) e.x = (unit(rng) - 0.5) * 0.4 * kRadius, e.y = (unit(rng) - 0.5) * 0.4 * kRadius;
    in_depth[k].offset = {b[0] * e.x + b[3] * e.y + b[6] * e.z, b[1] * e.x + b[4] * e.y + b[7] * e.z,
                          b[2] * e.x + b[5] * e.y + b[8] * e.z};
    in_depth[k].radius = kRadius;
    in_depth[k].side_radius = kRadius * std::sqrt(2.0);
    occluded_in_depth[k] = k < std::size_t(s.occluded);
    z += k + 1 < chain ? kChainStep : kSpacing;
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), rng);
  for (std::size_t k : order) {
    scene.objects.push_back(in_depth[k]);
    scene.occluded.push_back(occluded_in_depth[k]);
  }
  return scene;
}

// ---- Preliminary processing unit -----------------------------------------------------------------

PreliminaryResult preliminary_processing(const CountedScene& scene) {
  PreliminaryResult out;
  Tally t(out.counts);
  // "loading the position Po_i & orientation vectors of objects O_i and pilot": the pilot's part.
  t.host(kPilotWords);
  t.memory(kPilotMemory);
  // "calculating the matrix B": 4 O, 16 M, 4 A.
  out.B = matrix_b(t, scene.heading, scene.pitch, scene.roll);
  // "for i := 1, No": per object 34 R, 224 L, 9 M, 8 A, 6 C, 6 O.
  for (const CountedObject& o : scene.objects) {
    // "loading the position Po_i & orientation vectors of objects O_i": the object's record.
    t.host(kObjectWords);
    t.memory(kObjectMemory);
    // "transforming Po_i into the pilot coordinate system": 9 M, 6 A.
    const glm::dvec3 e = to_pilot(t, out.B, o.offset);
    // "forming a 'visual' flag (V[i] = 1)": the sphere against the simple viewing pyramid
    // |x| <= z, |y| <= z (a side plane's sphere test is x - z <= R sqrt 2), behind the screen
    // (z + R > 0) and the far test: 2 A, 1 + 5 O, 6 C.
    const double side = t.add(e.z, o.side_radius);  // z + R sqrt 2: 1 A
    const double front = t.add(e.z, o.radius);      // z + R: 1 A
    const double low = t.negate(side);              // -(z + R sqrt 2): 1 O
    const bool screen = t.less(0.0, front);         // 6 C, one per plane of the pyramid
    const bool deep = t.less(e.z, kFarPlane);
    const bool right = !t.less(side, e.x), left = !t.less(e.x, low);
    const bool top = !t.less(side, e.y), bottom = !t.less(e.y, low);
    // V[i]: the six outcomes ANDed, 5 O.
    const bool v = t.both(t.both(t.both(t.both(t.both(screen, deep), right), left), top), bottom);
    out.centre.push_back(e);
    out.visible.push_back(v ? 1 : 0);
  }
  return out;
}

// ---- Preliminary sorting unit --------------------------------------------------------------------

namespace {

// "if (distance between the object SP[j] and the object SP[i] less than the sum of the extent
// radiuses?) then marking the objects SP[i], SP[j]": 3 A + 3 M + 2 A (squared distance), 1 A + 1 M
// (squared sum of radii), 1 C, 20 L; with the loop's index j (1 A) 7 A, 4 M, 1 C, 20 L.
void sphere_test(Tally& t, const CountedScene& scene, const PreliminaryResult& pre, std::uint32_t a, std::uint32_t b,
                 SortingResult& out) {
  t.memory(kPairMemory);
  const glm::dvec3 &ca = pre.centre[a], &cb = pre.centre[b];
  const double dx = t.sub(ca.x, cb.x), dy = t.sub(ca.y, cb.y), dz = t.sub(ca.z, cb.z);
  const double d2 = t.add(t.add(t.mul(dx, dx), t.mul(dy, dy)), t.mul(dz, dz));
  const double r = t.add(scene.objects[a].radius, scene.objects[b].radius);
  if (t.less(d2, t.mul(r, r))) out.occluded[a] = out.occluded[b] = 1;
  ++out.pair_tests;
}

}  // namespace

SortingResult preliminary_sorting(const CountedScene& scene, const PreliminaryResult& pre, PairTests pairs) {
  SortingResult out;
  Tally t(out.counts);
  t.host(kSortingWords);  // the unit's frame data from the host: 25 R
  const std::size_t n = scene.objects.size();
  out.occluded.assign(n, 0);
  // "for i := 1, No {depth sorting of potentially visible objects (V[i] = 1); forming the priority
  // list SP[1..Nov]}": per object the V[i] test (1 C), 36 R and 70 L. The sort is the hardware
  // sorter's (keys in, SP out: memory traffic in kSortMemory); the table has no comparison for it.
  std::vector<std::uint32_t> sp;
  for (std::uint32_t i = 0; i < n; ++i) {
    t.host(kSortWords);
    t.memory(kSortMemory);
    if (t.test(pre.visible[i] != 0)) sp.push_back(i);
  }
  std::stable_sort(sp.begin(), sp.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return pre.centre[a].z < pre.centre[b].z; });
  // "for i := 1, Nov {for j := i+1, Nov {if (distance ...) marking ...}}".
  if (pairs == PairTests::kNeighbours) {
    // The table's reading: j = i + 1 only (Nov - 1 tests).
    for (std::size_t i = 0; i + 1 < sp.size(); ++i) {
      const std::size_t j = t.add_index(i, 1);  // j := i + 1: 1 A
      sphere_test(t, scene, pre, sp[i], sp[j], out);
    }
  } else {
    // The pseudo-code's loop over all pairs i < j (Nov (Nov - 1) / 2 tests).
    for (std::size_t i = 0; i < sp.size(); ++i)
      for (std::size_t j = i + 1; j < sp.size(); ++j) {
        t.add_index(j, 0);  // the index j: 1 A per test, as in the neighbour loop
        sphere_test(t, scene, pre, sp[i], sp[j], out);
      }
  }
  out.priority = std::move(sp);
  return out;
}

// ---- Subobject sorter ----------------------------------------------------------------------------

SorterResult subobject_sorter(const CountedScene& scene, const PreliminaryResult& pre, const SortingResult& sorting,
                              const std::vector<std::uint8_t>& occluded) {
  SorterResult out;
  Tally t(out.counts);
  const std::uint32_t npl = scene.structure.planes, np = scene.structure.points;
  // "for i := 1, Nov {... forming the priority list QS[i] for the subobjects from i-th object}":
  // every object's list in its stored order, 1 + Npl (3 + 7 Np) words from the host and into memory
  // (the table charges every object, the occluded ones too: their lists are the merge's input).
  // The branch on the occlusion mark is not counted (the table has no per-object C here).
  std::vector<std::uint32_t> group;  // the occluded objects, in SP order
  for (std::uint32_t i : sorting.priority) {
    t.host(kListHeader);
    t.memory(kListHeader);
    for (std::uint32_t p = 0; p < npl; ++p) {
      t.host(kPlaneHeader + kPointWords * np);
      t.memory(kPlaneHeader + kPointWords * np);
    }
    ++out.lists;
    if (occluded[i]) group.push_back(i);
  }
  // "else {depth sorting of the subobjects for the group of the occluded objects; forming the
  // priority list QS[i] for the subobjects from the group}": the group's planes read with their
  // points for the distances (R 3 + 10 Np, L 63 + 58 Np per plane) ...
  std::uint64_t remaining = 0;
  for (std::size_t g = 0; g < group.size(); ++g)
    for (std::uint32_t p = 0; p < npl; ++p, ++remaining) {
      t.host(kOccludedPlaneWords + kOccludedPointWords * np);
      t.memory(kOccludedPlaneMemory + kOccludedPointMemory * np);
    }
  // ... and merged as the seed's two-list merge, generalised to the group's lists: "if (DI[ni] >=
  // DJ[nj]) then QS[is] = SP[i][ni] else QS[is] = SP[j][nj]": the farther head first (ties: the
  // earlier list), an exhausted list a sentinel that loses every decision. Every entry but the last
  // is placed by a decision that evaluates its plane at its Np points (2 C, 144 L, 27 A, 48 M, 9 D
  // a point: the table's); the last entry is the only one left and needs none.
  std::vector<glm::dvec2> rim(np);  // plane_point's ring, once
  for (std::uint32_t k = 0; k < np; ++k) rim[k] = ring(k, np);
  auto distance = [&](std::uint32_t object, std::uint32_t plane) {
    const double r = scene.objects[object].radius;
    const glm::dvec3 mid = pre.centre[object] + glm::dvec3(0, 0, plane_depth(r, plane, npl));
    glm::dvec3 sum(0);
    for (std::uint32_t k = 0; k < np; ++k) sum += mid + glm::dvec3(0.3 * r * rim[k].x, 0.3 * r * rim[k].y, 0);
    const glm::dvec3 c = sum / double(np);  // the plane's centre
    return std::sqrt(c.x * c.x + c.y * c.y + c.z * c.z);
  };
  using Head = std::pair<double, std::int64_t>;  // (distance of the list's head, -list): max first
  std::priority_queue<Head> heads;
  std::vector<std::uint32_t> next(group.size(), 0);
  for (std::size_t g = 0; g < group.size(); ++g) heads.push({distance(group[g], 0), -std::int64_t(g)});
  while (!heads.empty()) {
    if (remaining > 1) {
      t.charge(kDecisionPerPoint, np);
      ++out.decisions;
    }
    --remaining;
    const Head h = heads.top();
    heads.pop();
    const std::size_t g = std::size_t(-h.second);
    out.group.push_back({group[g], next[g]});
    out.group_distance.push_back(h.first);
    if (++next[g] < npl) heads.push({distance(group[g], next[g]), -std::int64_t(g)});
  }
  return out;
}

// ---- The three units together, closed forms, the table -------------------------------------------

ManagerCounts run_counted_manager(const ManagerStructure& s, PairTests pairs, std::uint64_t seed) {
  const CountedScene scene = make_counted_scene(s, seed);
  const PreliminaryResult pre = preliminary_processing(scene);
  const SortingResult sorting = preliminary_sorting(scene, pre, pairs);
  const SorterResult sorter = subobject_sorter(scene, pre, sorting, scene.occluded);
  return {pre.counts, sorting.counts, sorter.counts};
}

ManagerCounts model_formula_counts(const ManagerStructure& s, PairTests pairs) {
  const std::uint64_t no = s.objects, noc = s.occluded, npl = s.planes, np = s.points;
  const std::uint64_t tests = pairs == PairTests::kNeighbours ? no - 1 : no * (no - 1) / 2;
  const std::uint64_t n = noc * npl, decisions = n > 0 ? n - 1 : 0, w = npl * (3 + 7 * np) + 1;
  ManagerCounts c;
  c.processing = {25 + 34 * no, 6 * no, 4 + 6 * no, 241 + 224 * no, 4 + 8 * no, 16 + 9 * no, 0};
  c.sorting = {25 + 36 * no, no + tests, 0, 70 * no + 20 * tests, 7 * tests, 4 * tests, 0};
  c.sorter = {no * w + n * (3 + 10 * np),
              2 * np * decisions,
              0,
              no * w + n * (63 + 58 * np) + 144 * np * decisions,
              27 * np * decisions,
              48 * np * decisions,
              9 * np * decisions};
  return c;
}

TableCounts seed_table_counts(const ManagerStructure& s) {
  const std::int64_t no = std::int64_t(s.objects), noc = std::int64_t(s.occluded), npl = s.planes, np = s.points;
  TableCounts c;
  c.processing = {25 + 34 * no, 6 * no, 4 + 6 * no, 241 + 224 * no, 4 + 8 * no, 16 + 9 * no, 0};
  c.sorting = {25 + 36 * no, 2 * no - 1, 0, 90 * no - 20, 7 * no - 7, 4 * no - 4, 0};
  c.sorter = {noc * npl * (3 + 10 * npl) + no * (npl * (3 + 7 * np) + 1),
              (noc * npl - 1) * 2 * np,
              0,
              noc * (202 * npl * np + 63 * npl - 144 * np) + no * (npl * (3 + 7 * np) + 1),
              27 * np * (noc * npl - 1),
              48 * np * (noc * npl - 1),
              9 * np * (noc * npl - 1)};
  return c;
}

// ---- Capacity ------------------------------------------------------------------------------------

namespace {

template <class Counts>
double schedule_cycles(const CapacityQuestion& q, const UnitCounts<Counts>& c) {
  const double a = cycles(c.processing, q.cost), b = cycles(c.sorting, q.cost), d = cycles(c.sorter, q.cost);
  return q.schedule == UnitSchedule::kSequence ? a + b + d : std::max({a, b, d});
}

}  // namespace

double frame_cycles_of_run(const CapacityQuestion& q, const ManagerCounts& c) { return schedule_cycles(q, c); }

double frame_cycles(const CapacityQuestion& q, const ManagerStructure& s) {
  return q.source == CountSource::kModel ? schedule_cycles(q, model_formula_counts(s, q.pairs))
                                         : schedule_cycles(q, seed_table_counts(s));
}

std::uint64_t largest_objects(const CapacityQuestion& q, std::uint64_t occluded, std::uint32_t planes,
                              std::uint32_t points, std::uint64_t cap) {
  const double budget = q.budget();
  auto fits = [&](std::uint64_t no) { return frame_cycles(q, {no, occluded, planes, points}) <= budget; };
  std::uint64_t lo = std::max<std::uint64_t>(occluded, 1);
  if (lo > cap || !fits(lo)) return 0;
  std::uint64_t hi = lo;  // fits(lo); double until hi does not fit
  for (;;) {
    if (lo == cap) return cap;
    hi = std::min(cap, lo * 2);
    if (!fits(hi)) break;
    lo = hi;
  }
  while (hi - lo > 1) {
    const std::uint64_t mid = lo + (hi - lo) / 2;
    (fits(mid) ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace cig
