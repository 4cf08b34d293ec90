// Operation counts of seed 000's scene manager (SPEC A.7): the counted model a hardware architect
// uses to size the unit. Three functions RUN the seed's pseudo-code for a scene of the table's
// structure (No objects, Noc of them occluded, each object Npl planes of Np points) and count every
// operation by the seed's kinds as they go:
//
//   R  exchange with the host computer      L  memory read/write
//   C  comparison + conditional jump        A  addition (and subtraction)
//   O  logical instruction                  M  multiplication
//                                           D  division
//
//   preliminary_processing  loading the pilot's and objects' vectors, the matrix B, each object
//                           centre into pilot coordinates, the "visual" flag V[i];
//   preliminary_sorting     the depth sort into the priority list SP and the sphere tests that
//                           mark objects as occluding each other;
//   subobject_sorter        each object's subobject list QS[i]; for the occluded objects the
//                           distances of their planes and the merge into one priority list.
//
// Where the seed's table is self-consistent the counts equal its formulas exactly; where no
// per-step accounting consistent with the other entries can produce an entry, the model counts what
// its steps do and the entry is listed below with its derived formula. The per-step costs, and which
// of them the seed fixes and which are this model's split of a unit total, are documented next to
// each increment in operation_counts.cpp.
//
// The table's scene (what its formulas assume, and so what make_counted_scene builds): every object
// is potentially visible (Nov = No); the Noc occluded objects form ONE group whose N = Noc*Npl
// planes are merged into one list; sphere tests are made between NEIGHBOURS of the depth-sorted list
// SP (No - 1 of them: the table's C, A, M and L of the sorting unit are linear in No; the
// pseudo-code's loop "for j := i+1, Nov" over all pairs would make them quadratic, PairTests::kAll);
// the depth sort itself makes no counted comparison (the sorting unit's C = 2 No - 1 leaves one per
// object, the V[i] test, and one per neighbour pair: a comparison sort needs ~No log2 No; the sort
// is counted as the memory traffic of a hardware sorter, keys in and SP out).
//
// The table's entries (unit: entry = formula), and what the model counts:
//
//   preliminary processing   R = 25 + 34 No    C = 6 No    O = 4 + 6 No    L = 241 + 224 No
//                            A = 4 + 8 No      M = 16 + 9 No               D = 0
//     all as printed. A = 8 per object has room for B's rotation (6 A) and the visibility test
//     (2 A) but not for the translation Po_i - Po_pilot (3 A): the host sends each object's
//     position relative to the pilot. M = 16 is B from three angles without sharing s_theta*s_psi
//     and s_theta*c_psi (sharing them would make it 14).
//   preliminary sorting      R = 25 + 36 No    C = 2 No - 1    L = 90 No - 20
//                            A = 7 No - 7      M = 4 No - 4    O = D = 0
//     all as printed (No >= 1), with the neighbour reading above.
//   subobject sorter (N = Noc*Npl planes of the occluded objects, W = Npl*(3 + 7 Np) + 1)
//     R = Noc*Npl*(3 + 10*Npl) + No*W        INCONSISTENT: quadratic in Npl, while every other
//         entry touches each plane a fixed number of times (C, A, M, D are linear in Npl: one
//         merge decision per plane); no step reads Npl words per plane. Model: Npl -> Np in the
//         bracket, R = N*(3 + 10 Np) + No*W (a plane's 3 words and 10 per point; 7 of them as in W).
//     C = (N - 1)*2*Np,  A = 27*Np*(N - 1),  M = 48*Np*(N - 1),  D = 9*Np*(N - 1)
//         as printed for Noc >= 1 (N - 1 merge decisions, the last plane needs none; each decision
//         evaluates its plane at its Np points). INCONSISTENT at Noc = 0: the formulas are negative
//         (-2 Np, -27 Np, -48 Np, -9 Np); the model counts 0 (max(N - 1, 0) decisions).
//     L = Noc*(202*Npl*Np + 63*Npl - 144*Np) + No*W    INCONSISTENT for Noc >= 2: the -144 Np part
//         is once per occluded object, i.e. a step made Noc*(Npl - 1) times, which no other kind
//         has (C, A, M, D count N - 1 decisions for the group, once per plane but one); a step
//         with 144 Np memory accesses and no comparison cannot be a merge decision. Read as a
//         misplaced bracket, the -1 of the group's N - 1 decisions: L = N*(202 Np + 63) - 144 Np
//         + No*W (= 58 Np per plane's point + 63 per plane + 144 Np per decision); equal to the
//         table at Noc = 1, and at Noc = 0 (no group, no decision).
//     O = 0 as printed.
//
// Not counted by the table and so not by the model: the test "is the object marked as occluded?"
// of the sorter's loop (no per-object C), the mixing of lists when Nc < groups, and the channel
// loading loop. seed_table_counts gives the table's formulas as printed (negative where they are);
// model_formula_counts the model's closed forms, which verif/unit/test_operation_counts.cpp checks
// against the runs.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "common/operation_units.hpp"

namespace cig {

// The table's formulas as printed can be negative (the subobject sorter at Noc = 0).
struct SignedCounts {
  std::int64_t R = 0, C = 0, O = 0, L = 0, A = 0, M = 0, D = 0;
};

// Cycles per operation of each kind (a stated cost, not a measurement).
struct OperationCost {
  double R = 1, C = 1, O = 1, L = 1, A = 1, M = 1, D = 1;
};
double cycles(const OperationCounts& c, const OperationCost& cost);
double cycles(const SignedCounts& c, const OperationCost& cost);

// The table's scene: No objects, Noc of them occluded, each object Npl planes of Np points.
struct ManagerStructure {
  std::uint64_t objects = 1;   // No >= 1
  std::uint64_t occluded = 0;  // Noc, 0..No
  std::uint32_t planes = 1;    // Npl >= 1
  std::uint32_t points = 3;    // Np >= 3
};

// Sphere tests of the preliminary sorting unit: between neighbours of SP (the table's No - 1), or
// between all pairs i < j as the pseudo-code's loop is written (Nov (Nov - 1) / 2).
enum class PairTests { kNeighbours, kAll };

// One object as the host sends it: its centre relative to the pilot (world axes) and the radius of
// its bounding sphere.
struct CountedObject {
  glm::dvec3 offset{0};
  double radius = 1;
  double side_radius = 1;  // radius * sqrt(2), stored with the object: the side planes' threshold
};

// A scene of the structure: every object inside the simple viewing pyramid; the Noc occluded
// objects a chain of overlapping spheres, consecutive in depth (so the neighbour test and the
// all-pairs test mark the same objects); the others spaced so that no two spheres meet. Database
// order shuffled. A single occluded object cannot come out of the pair marking (marks come in
// pairs): for Noc = 1 no sphere overlaps, and `occluded` marks the one object the sorter treats as
// occluded.
struct CountedScene {
  ManagerStructure structure;
  double heading = 0, pitch = 0, roll = 0;  // the pilot's orientation, radians
  std::vector<CountedObject> objects;       // database order
  std::vector<std::uint8_t> occluded;       // by design, per object
};
CountedScene make_counted_scene(const ManagerStructure& s, std::uint64_t seed = 1);

// Point k of plane p of object i in pilot coordinates, from its centre there: the planes of an
// object lie at decreasing depth (p = 0 the farthest), so each object's stored list is back to
// front, as the seed's two-list merge expects of DI and DJ.
glm::dvec3 plane_point(const glm::dvec3& centre, double radius, std::uint32_t plane, std::uint32_t planes,
                       std::uint32_t point, std::uint32_t points);

struct PreliminaryResult {
  OperationCounts counts;
  std::array<double, 9> B{};          // row-major, world -> pilot
  std::vector<glm::dvec3> centre;     // each object's centre in pilot coordinates
  std::vector<std::uint8_t> visible;  // V[i]
};
PreliminaryResult preliminary_processing(const CountedScene& scene);

struct SortingResult {
  OperationCounts counts;
  std::vector<std::uint32_t> priority;  // SP[1..Nov]: the visible objects, nearest first
  std::vector<std::uint8_t> occluded;   // marked as occluding another object, per object
  std::uint64_t pair_tests = 0;
};
SortingResult preliminary_sorting(const CountedScene& scene, const PreliminaryResult& pre,
                                  PairTests pairs = PairTests::kNeighbours);

struct SubobjectRef {
  std::uint32_t object, plane;
};
struct SorterResult {
  OperationCounts counts;
  std::uint64_t lists = 0;             // QS[i] formed, one per object of SP
  std::vector<SubobjectRef> group;     // the occluded objects' QS: their planes, back to front
  std::vector<double> group_distance;  // the distance of each entry of `group` (non-increasing)
  std::uint64_t decisions = 0;         // merge decisions: max(N - 1, 0)
};
// `occluded`: the objects the sorter treats as occluded (SortingResult::occluded, or the scene's).
SorterResult subobject_sorter(const CountedScene& scene, const PreliminaryResult& pre, const SortingResult& sorting,
                              const std::vector<std::uint8_t>& occluded);

template <class Counts>
struct UnitCounts {
  Counts processing, sorting, sorter;  // preliminary processing unit, preliminary sorting unit, subobject sorter
};
using ManagerCounts = UnitCounts<OperationCounts>;
using TableCounts = UnitCounts<SignedCounts>;

// The three units run on make_counted_scene(s, seed), the sorter with the scene's occluded objects.
ManagerCounts run_counted_manager(const ManagerStructure& s, PairTests pairs = PairTests::kNeighbours,
                                  std::uint64_t seed = 1);
// The model's counts in closed form (equal to run_counted_manager; tested).
ManagerCounts model_formula_counts(const ManagerStructure& s, PairTests pairs = PairTests::kNeighbours);
// The seed's table as printed.
TableCounts seed_table_counts(const ManagerStructure& s);

// ---- Capacity: the largest scene one frame holds ------------------------------------------------
enum class UnitSchedule {
  kSequence,  // the three units one after another: frame cycles = the sum of the units'
  kPipeline,  // each unit works on its own frame: frame cycles = the slowest unit's
};
enum class CountSource { kModel, kSeedTable };

struct CapacityQuestion {
  double clock_mhz = 100, frame_hz = 25;
  OperationCost cost;
  UnitSchedule schedule = UnitSchedule::kSequence;
  PairTests pairs = PairTests::kNeighbours;  // the model's; the table has neighbours only
  CountSource source = CountSource::kModel;
  double budget() const { return clock_mhz * 1e6 / frame_hz; }  // cycles per frame
};
// Frame cycles of a scene of structure s, from q.source's counts.
double frame_cycles(const CapacityQuestion& q, const ManagerStructure& s);
// Frame cycles of counts already made (a run of the three units), by q's costs and schedule.
double frame_cycles_of_run(const CapacityQuestion& q, const ManagerCounts& c);

// The largest No (>= max(Noc, 1)) whose frame cycles fit the budget; 0 when not even the smallest
// does; `cap` when cap objects still fit (the search stops there). Frame cycles grow with No.
std::uint64_t largest_objects(const CapacityQuestion& q, std::uint64_t occluded, std::uint32_t planes,
                              std::uint32_t points, std::uint64_t cap = 10000000);

}  // namespace cig
