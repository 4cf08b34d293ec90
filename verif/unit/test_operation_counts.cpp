// Seed 000's operation-count table against the counted model of the scene manager
// (cmodel/studies/operation_counts.hpp):
//  * over random scenes of the table's structure (No 1..5000, Noc 0..No, Npl 1..64, Np 3..16), the
//    counts by kind of each unit, from RUNNING the three units, equal the table's formulas, written
//    out below as printed in the seed (shared/seeds/000, section 5), for every self-consistent
//    entry, and the derived formulas for the three that are not (the subobject sorter's R, its L for
//    Noc >= 2, and its C, A, M, D at Noc = 0, where the table is negative);
//  * the runs do what the pseudo-code says: every object visible, SP in depth order, the occluded
//    objects (and only they) marked, the group's list holding each of its planes once, back to
//    front, after max(N - 1, 0) decisions;
//  * the model's closed forms equal its runs, also with the pseudo-code's all-pairs sphere tests;
//  * B is a rotation; largest_objects is the boundary of the frame budget.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "studies/operation_counts.hpp"

namespace cig {

void PrintTo(const OperationCounts& c, std::ostream* os) { *os << to_string(c); }

namespace {

struct Kinds {
  std::int64_t R, C, O, L, A, M, D;
};

Kinds kinds(const OperationCounts& c) {
  return {std::int64_t(c.R), std::int64_t(c.C), std::int64_t(c.O), std::int64_t(c.L),
          std::int64_t(c.A), std::int64_t(c.M), std::int64_t(c.D)};
}

void expect_counts(const char* unit, const Kinds& want, const OperationCounts& got_counts) {
  const Kinds got = kinds(got_counts);
  EXPECT_EQ(got.R, want.R) << unit << " R";
  EXPECT_EQ(got.C, want.C) << unit << " C";
  EXPECT_EQ(got.O, want.O) << unit << " O";
  EXPECT_EQ(got.L, want.L) << unit << " L";
  EXPECT_EQ(got.A, want.A) << unit << " A";
  EXPECT_EQ(got.M, want.M) << unit << " M";
  EXPECT_EQ(got.D, want.D) << unit << " D";
}

// ---- The seed's table, as printed ("-" is 0) -----------------------------------------------------

Kinds table_preliminary_processing(std::int64_t No) {
  return {/*R*/ 25 + 34 * No, /*C*/ 6 * No,      /*O*/ 4 + 6 * No, /*L*/ 241 + 224 * No,
          /*A*/ 4 + 8 * No,   /*M*/ 16 + 9 * No, /*D*/ 0};
}

Kinds table_preliminary_sorting(std::int64_t No) {
  return {/*R*/ 25 + 36 * No, /*C*/ 2 * No - 1, /*O*/ 0, /*L*/ 90 * No - 20,
          /*A*/ 7 * No - 7,   /*M*/ 4 * No - 4, /*D*/ 0};
}

Kinds table_subobject_sorter(std::int64_t No, std::int64_t Noc, std::int64_t Npl, std::int64_t Np) {
  return {/*R*/ Noc * Npl * (3 + 10 * Npl) + No * (Npl * (3 + 7 * Np) + 1),
          /*C*/ (Noc * Npl - 1) * 2 * Np,
          /*O*/ 0,
          /*L*/ Noc * (202 * Npl * Np + 63 * Npl - 144 * Np) + No * (Npl * (3 + 7 * Np) + 1),
          /*A*/ 27 * Np * (Noc * Npl - 1),
          /*M*/ 48 * Np * (Noc * Npl - 1),
          /*D*/ 9 * Np * (Noc * Npl - 1)};
}

// What the subobject sorter must count: the table where it is consistent, the derived formula where
// it is not (operation_counts.hpp gives the reasons).
Kinds expected_subobject_sorter(std::int64_t No, std::int64_t Noc, std::int64_t Npl, std::int64_t Np) {
  Kinds k = table_subobject_sorter(No, Noc, Npl, Np);
  // R: the quadratic 10 Npl read as 10 Np.
  k.R = Noc * Npl * (3 + 10 * Np) + No * (Npl * (3 + 7 * Np) + 1);
  if (Noc == 0) {
    // C, A, M, D: negative in the table; no group, no decision. (L: the table's, = No W.)
    k.C = k.A = k.M = k.D = 0;
  } else {
    // L: the -144 Np of the group's N - 1 decisions, once, not once per occluded object.
    k.L = Noc * (202 * Npl * Np + 63 * Npl) - 144 * Np + No * (Npl * (3 + 7 * Np) + 1);
  }
  return k;
}

// One random scene: runs the units one by one, checks the counts and what the units did.
void check_structure(const ManagerStructure& s, std::uint64_t seed) {
  SCOPED_TRACE("No=" + std::to_string(s.objects) + " Noc=" + std::to_string(s.occluded) +
               " Npl=" + std::to_string(s.planes) + " Np=" + std::to_string(s.points));
  const std::int64_t No = std::int64_t(s.objects), Noc = std::int64_t(s.occluded), Npl = s.planes, Np = s.points;
  const CountedScene scene = make_counted_scene(s, seed);
  const PreliminaryResult pre = preliminary_processing(scene);
  const SortingResult sorting = preliminary_sorting(scene, pre);
  const SorterResult sorter = subobject_sorter(scene, pre, sorting, scene.occluded);

  // The counts against the table.
  expect_counts("preliminary processing", table_preliminary_processing(No), pre.counts);
  expect_counts("preliminary sorting", table_preliminary_sorting(No), sorting.counts);
  expect_counts("subobject sorter", expected_subobject_sorter(No, Noc, Npl, Np), sorter.counts);
  // The documented differences of the inconsistent entries.
  const Kinds table = table_subobject_sorter(No, Noc, Npl, Np), got = kinds(sorter.counts);
  EXPECT_EQ(table.R - got.R, 10 * Noc * Npl * (Npl - Np));
  EXPECT_EQ(table.L - got.L, Noc == 0 ? 0 : -144 * Np * (Noc - 1));
  if (Noc == 0) {
    EXPECT_EQ(table.C, -2 * Np);  // the table's count is negative there
  }

  // What the units did.
  EXPECT_EQ(std::count(pre.visible.begin(), pre.visible.end(), 1), No);
  ASSERT_EQ(sorting.priority.size(), std::size_t(No));
  for (std::size_t k = 1; k < sorting.priority.size(); ++k)
    ASSERT_LE(pre.centre[sorting.priority[k - 1]].z, pre.centre[sorting.priority[k]].z);
  EXPECT_EQ(sorting.pair_tests, std::uint64_t(No - 1));
  if (Noc != 1) {
    EXPECT_EQ(sorting.occluded, scene.occluded);
  } else {
    EXPECT_EQ(std::count(sorting.occluded.begin(), sorting.occluded.end(), 1), 0);  // marks come in pairs
  }
  EXPECT_EQ(sorter.lists, std::uint64_t(No));
  ASSERT_EQ(sorter.group.size(), std::size_t(Noc * Npl));
  EXPECT_EQ(sorter.decisions, std::uint64_t(std::max<std::int64_t>(Noc * Npl - 1, 0)));
  std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
  for (std::size_t k = 0; k < sorter.group.size(); ++k) {
    const SubobjectRef& e = sorter.group[k];
    EXPECT_TRUE(scene.occluded[e.object]);
    EXPECT_LT(e.plane, s.planes);
    EXPECT_TRUE(seen.insert({e.object, e.plane}).second) << "plane listed twice";
    if (k > 0) { ASSERT_GE(sorter.group_distance[k - 1], sorter.group_distance[k]) << "not back to front at " << k; }
  }
  // The model's closed form is what it runs.
  const ManagerCounts closed = model_formula_counts(s);
  EXPECT_EQ(closed.processing, pre.counts);
  EXPECT_EQ(closed.sorting, sorting.counts);
  EXPECT_EQ(closed.sorter, sorter.counts);
}

TEST(OperationCounts, TableFormulasOverRandomStructures) {
  std::mt19937_64 rng(2024);
  auto pick = [&](std::uint64_t lo, std::uint64_t hi) {
    return std::uniform_int_distribution<std::uint64_t>(lo, hi)(rng);
  };
  for (int k = 0; k < 200; ++k) {
    ManagerStructure s;
    s.objects = pick(1, 5000);
    // A third of the scenes with few occluded objects (0, 1, 2: the table's edge cases).
    s.occluded = k % 3 == 0 ? std::min<std::uint64_t>(s.objects, pick(0, 2)) : pick(0, s.objects);
    s.planes = std::uint32_t(pick(1, 64));
    s.points = std::uint32_t(pick(3, 16));
    check_structure(s, std::uint64_t(k) + 1);
    if (HasFatalFailure()) return;
  }
}

TEST(OperationCounts, TableFormulasAtTheEdges) {
  for (const ManagerStructure& s :
       {ManagerStructure{1, 0, 1, 3}, ManagerStructure{1, 1, 1, 3}, ManagerStructure{1, 1, 64, 16},
        ManagerStructure{2, 2, 1, 3}, ManagerStructure{5000, 5000, 64, 16}, ManagerStructure{5000, 0, 64, 16},
        ManagerStructure{1000, 60, 24, 4}})
    check_structure(s, 7);
}

TEST(OperationCounts, AllPairsAsThePseudoCodeIsWritten) {
  std::mt19937_64 rng(5);
  for (int k = 0; k < 40; ++k) {
    const std::uint64_t no = 1 + rng() % 400;
    const ManagerStructure s{no, rng() % (no + 1), std::uint32_t(1 + rng() % 16), std::uint32_t(3 + rng() % 6)};
    const CountedScene scene = make_counted_scene(s, k);
    const PreliminaryResult pre = preliminary_processing(scene);
    const SortingResult all = preliminary_sorting(scene, pre, PairTests::kAll);
    const SortingResult neighbours = preliminary_sorting(scene, pre, PairTests::kNeighbours);
    EXPECT_EQ(all.occluded, neighbours.occluded);  // the chain: the same objects marked
    const std::int64_t No = std::int64_t(no), pairs = No * (No - 1) / 2;
    EXPECT_EQ(all.pair_tests, std::uint64_t(pairs));
    expect_counts("all pairs", {25 + 36 * No, No + pairs, 0, 70 * No + 20 * pairs, 7 * pairs, 4 * pairs, 0},
                  all.counts);
    const ManagerCounts run = run_counted_manager(s, PairTests::kAll, k);
    const ManagerCounts closed = model_formula_counts(s, PairTests::kAll);
    EXPECT_EQ(run.processing, closed.processing);
    EXPECT_EQ(run.sorting, closed.sorting);
    EXPECT_EQ(run.sorter, closed.sorter);
  }
}

TEST(OperationCounts, MatrixBIsARotationAndTheCentresAreInView) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const CountedScene scene = make_counted_scene({50, 10, 4, 4}, seed);
    const PreliminaryResult pre = preliminary_processing(scene);
    const auto& b = pre.B;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double dot = b[3 * i] * b[3 * j] + b[3 * i + 1] * b[3 * j + 1] + b[3 * i + 2] * b[3 * j + 2];
        EXPECT_NEAR(dot, i == j ? 1.0 : 0.0, 1e-12);
      }
    const double det =
        b[0] * (b[4] * b[8] - b[5] * b[7]) - b[1] * (b[3] * b[8] - b[5] * b[6]) + b[2] * (b[3] * b[7] - b[4] * b[6]);
    EXPECT_NEAR(det, 1.0, 1e-12);
    for (const auto& c : pre.centre) {
      EXPECT_GT(c.z, 0);
      EXPECT_LE(std::abs(c.x), c.z);
      EXPECT_LE(std::abs(c.y), c.z);
    }
  }
}

TEST(OperationCounts, LargestObjectsIsTheBudgetsBoundary) {
  for (CountSource source : {CountSource::kModel, CountSource::kSeedTable})
    for (UnitSchedule schedule : {UnitSchedule::kSequence, UnitSchedule::kPipeline})
      for (PairTests pairs : {PairTests::kNeighbours, PairTests::kAll})
        for (std::uint64_t noc : {0, 20, 60, 200})
          for (std::uint32_t npl : {6, 24, 48}) {
            CapacityQuestion q;
            q.source = source, q.schedule = schedule, q.pairs = pairs;
            q.cost.L = 2, q.cost.D = 8;
            const std::uint64_t no = largest_objects(q, noc, npl, 4);
            if (no == 0) {
              EXPECT_GT(frame_cycles(q, {std::max<std::uint64_t>(noc, 1), noc, npl, 4}), q.budget());
              continue;
            }
            EXPECT_GE(no, noc);
            EXPECT_LE(frame_cycles(q, {no, noc, npl, 4}), q.budget());
            EXPECT_GT(frame_cycles(q, {no + 1, noc, npl, 4}), q.budget());
          }
  // The search stops at the cap.
  CapacityQuestion free;
  free.cost = {0, 0, 0, 0, 0, 0, 0};
  EXPECT_EQ(largest_objects(free, 0, 6, 4, 12345), 12345u);
  // At one cycle per operation, 100 MHz and 25 Hz: 4,000,000 cycles; the model's frame at 1000
  // objects, 60 occluded, 24 planes of 4 points, in sequence, from the formulas by hand:
  // 290 + 287 No (processing) + 139 No - 7 (sorting) + 1490 No + 1440 * 43 + 1440 * 871 - 576
  // + 344 * 1439 (sorter).
  CapacityQuestion q;
  const double by_hand =
      290 + 287 * 1000.0 + 139 * 1000.0 - 7 + 1490 * 1000.0 + 1440 * 43 + 1440 * 871 - 576 + 344 * 1439;
  EXPECT_DOUBLE_EQ(frame_cycles(q, {1000, 60, 24, 4}), by_hand);
  EXPECT_EQ(q.budget(), 4e6);
}

}  // namespace
}  // namespace cig
