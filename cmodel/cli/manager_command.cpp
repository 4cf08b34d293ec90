// cig manager --capacity [--clock-ns T] [--rate HZ] [--cost R=1,C=1,O=1,L=1,A=1,M=1,D=1]
//                        [--occluded LIST] [--planes LIST] [--points LIST]
//                        [--schedule sequence|pipeline] [--pairs neighbours|all]
// Seed 000's scene manager as a counted model (cmodel/studies/operation_counts.hpp): the largest No
// one frame holds, for each Noc and object shape Npl x Np, from the model's counts and from the
// seed's table as printed; the frame load of the seed's claim (No = 1000, Noc = 60) under each
// assumption; and the verdict on the claim.
#include "cli/manager_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "common/error.hpp"
#include "studies/operation_counts.hpp"

namespace cig::cli {

namespace {

constexpr const char* kUsage =
    "cig manager --capacity [--clock-ns T] [--rate HZ] [--cost R=1,C=1,O=1,L=1,A=1,M=1,D=1] [--occluded LIST] "
    "[--planes LIST] [--points LIST] [--schedule sequence|pipeline] [--pairs neighbours|all]";
constexpr std::uint64_t kCap = 10000000;  // the search for No stops here
constexpr std::uint64_t kClaimObjects = 1000, kClaimOccluded = 60;
constexpr std::uint32_t kMaxPlanes = 4096, kMaxPoints = 4096;

struct Shape {
  std::uint32_t planes, points;
};

std::string number(double v) {
  std::ostringstream s;
  if (v == std::floor(v) && std::abs(v) < 1e15) s << std::fixed << std::setprecision(0) << v;
  else s << std::setprecision(6) << v;
  return s.str();
}

std::string shape_name(const Shape& s) { return std::to_string(s.planes) + "x" + std::to_string(s.points); }

// --cost KIND=CYCLES,... : the kinds not named cost 1.
OperationCost parse_cost(const std::string& text) {
  OperationCost cost;
  if (text.empty()) return cost;
  std::set<char> seen;
  std::stringstream items(text);
  std::string item;
  while (std::getline(items, item, ',')) {
    const std::size_t eq = item.find('=');
    if (eq != 1)
      throw InputError("", "--cost", "'" + item + "' is not of the form KIND=CYCLES (kinds R, C, O, L, A, M, D)");
    const char kind = item[0];
    double* slot = kind == 'R'   ? &cost.R
                   : kind == 'C' ? &cost.C
                   : kind == 'O' ? &cost.O
                   : kind == 'L' ? &cost.L
                   : kind == 'A' ? &cost.A
                   : kind == 'M' ? &cost.M
                   : kind == 'D' ? &cost.D
                                 : nullptr;
    if (!slot)
      throw InputError(
          "", "--cost",
          "'" + item + "': unknown operation kind '" + std::string(1, kind) + "' (kinds R, C, O, L, A, M, D)");
    if (!seen.insert(kind).second) throw InputError("", "--cost", "'" + item + "': kind " + kind + " given twice");
    const std::string value = item.substr(eq + 1);
    char* end = nullptr;
    const double v = value.empty() ? NAN : std::strtod(value.c_str(), &end);
    if (value.empty() || end != value.c_str() + value.size() || !(v >= 0 && v <= 1e6))
      throw InputError("", "--cost", "'" + item + "': cycles per operation must be a number from 0 to 1e6");
    *slot = v;
  }
  if (text.back() == ',') throw InputError("", "--cost", "'" + text + "' ends with a comma");
  return cost;
}

std::string costs_text(const OperationCost& c) {
  return "R=" + number(c.R) + " C=" + number(c.C) + " O=" + number(c.O) + " L=" + number(c.L) + " A=" + number(c.A) +
         " M=" + number(c.M) + " D=" + number(c.D);
}

std::string capacity_text(std::uint64_t no) {
  if (no == 0) return "-";
  if (no >= kCap) return ">=" + std::to_string(kCap);
  return std::to_string(no);
}

// The model's No re-counted by running the three units at No and No + 1 (the closed form is what
// the capacity search uses; a disagreement is a bug of the model, not an input error).
bool check_by_running(const CapacityQuestion& q, std::uint64_t no, std::uint64_t noc, const Shape& s) {
  if (no == 0 || no >= 100000 || (q.pairs == PairTests::kAll && no >= 5000)) return false;
  const double budget = q.budget();
  const double at = frame_cycles_of_run(q, run_counted_manager({no, noc, s.planes, s.points}, q.pairs));
  const double past = frame_cycles_of_run(q, run_counted_manager({no + 1, noc, s.planes, s.points}, q.pairs));
  if (!(at <= budget && past > budget))
    throw std::logic_error("cig manager: the counted run disagrees with the closed form at No = " + std::to_string(no));
  return true;
}

// The largest Npl (up to kMaxPlanes) whose frame at the claim's No, Noc fits; 0 if none.
std::uint32_t largest_planes(const CapacityQuestion& q, std::uint32_t points) {
  std::uint32_t best = 0;
  for (std::uint32_t npl = 1; npl <= kMaxPlanes; ++npl) {
    if (frame_cycles(q, {kClaimObjects, kClaimOccluded, npl, points}) > q.budget()) break;
    best = npl;
  }
  return best;
}

void print_capacity_table(const CapacityQuestion& q, const std::vector<long long>& occluded,
                          const std::vector<Shape>& shapes, const char* title, int& checked) {
  std::cout << "\nlargest No in one frame, " << title << " ('-': not even No = Noc fits)\n";
  std::cout << std::left << std::setw(10) << "Npl x Np" << std::right;
  for (long long noc : occluded) std::cout << std::setw(10) << ("Noc=" + std::to_string(noc));
  std::cout << "\n";
  for (const Shape& s : shapes) {
    std::cout << std::left << std::setw(10) << shape_name(s) << std::right;
    for (long long noc : occluded) {
      const std::uint64_t no = largest_objects(q, std::uint64_t(noc), s.planes, s.points, kCap);
      if (q.source == CountSource::kModel && check_by_running(q, no, std::uint64_t(noc), s)) ++checked;
      std::cout << std::setw(10) << capacity_text(no);
    }
    std::cout << "\n";
  }
}

// "holds for 6x4, 12x4 (largest No ...); not for 48x4 (largest No 564)"
std::string verdict(const CapacityQuestion& q, const std::vector<Shape>& shapes, const std::set<std::uint32_t>& np) {
  std::string yes, no;
  for (const Shape& s : shapes) {
    const std::uint64_t n = largest_objects(q, kClaimOccluded, s.planes, s.points, kCap);
    std::string& list = n >= kClaimObjects ? yes : no;
    list += (list.empty() ? "" : ", ") + shape_name(s) + " (" + capacity_text(n) + ")";
  }
  std::string out = yes.empty() ? "holds for no shape listed" : "holds for " + yes;
  if (!no.empty()) out += "; not for " + no;
  out += "; the largest Npl for the claim:";
  bool first = true;
  for (std::uint32_t p : np) {
    const std::uint32_t n = largest_planes(q, p);
    out += std::string(first ? " " : ", ") +
           (n == 0            ? "none"
            : n >= kMaxPlanes ? ">=" + std::to_string(n)
                              : std::to_string(n)) +
           " at Np = " + std::to_string(p);
    first = false;
  }
  return out;
}

// The header: the question and its assumptions.
void print_assumptions(const CapacityQuestion& q) {
  const bool pipelined = q.schedule == UnitSchedule::kPipeline;
  std::cout
      << "cig manager --capacity: seed 000's scene manager as a counted model (cmodel/studies/operation_counts.hpp)\n"
      << "clock " << number(q.clock_mhz) << " MHz, frame rate " << number(q.frame_hz) << " Hz: " << number(q.budget())
      << " cycles a frame; cycles per operation " << costs_text(q.cost) << "\n"
      << "assumptions: "
      << (pipelined ? "the three units pipelined (each works on its own frame; a frame = the slowest unit)"
                    : "the three units in sequence (a frame = the sum of their cycles)")
      << ";\n  every object potentially visible (Nov = No); the Noc occluded objects one group;\n  sphere tests "
      << (q.pairs == PairTests::kAll ? "between all pairs of SP (the pseudo-code's loop)"
                                     : "between neighbours of SP (the table's No - 1)")
      << "; the depth sort counted as memory traffic (the table has no comparison for it)\n";
}

// The frame load of the seed's claim under each assumption.
void print_claim_loads(const CapacityQuestion& q, const std::vector<Shape>& shapes) {
  // The claim's frame under each assumption.
  CapacityQuestion seq = q, pipe = q, all = q;
  seq.schedule = UnitSchedule::kSequence, seq.pairs = PairTests::kNeighbours;
  pipe.schedule = UnitSchedule::kPipeline, pipe.pairs = PairTests::kNeighbours;
  all.schedule = UnitSchedule::kSequence, all.pairs = PairTests::kAll;
  CapacityQuestion table_seq = seq;
  table_seq.source = CountSource::kSeedTable;
  std::cout << "\nframe load at No = " << kClaimObjects << ", Noc = " << kClaimOccluded
            << " (cycles / cycles a frame; <= 1 fits)\n"
            << std::left << std::setw(10) << "Npl x Np" << std::right << std::setw(20) << "model, in sequence"
            << std::setw(18) << "model, pipelined" << std::setw(22) << "table, in sequence" << std::setw(31)
            << "model all pairs, in sequence"
            << "\n";
  for (const Shape& s : shapes) {
    const ManagerStructure m{kClaimObjects, kClaimOccluded, s.planes, s.points};
    auto load = [&](const CapacityQuestion& x) {
      std::ostringstream o;
      o << std::fixed << std::setprecision(3) << frame_cycles(x, m) / x.budget();
      return o.str();
    };
    std::cout << std::left << std::setw(10) << shape_name(s) << std::right << std::setw(20) << load(seq)
              << std::setw(18) << load(pipe) << std::setw(22) << load(table_seq) << std::setw(31) << load(all) << "\n";
  }
}

// The model's cycles per unit at the claim.
void print_unit_cycles(const CapacityQuestion& q, const std::vector<Shape>& shapes) {
  std::cout << "\nmodel cycles per unit at No = " << kClaimObjects << ", Noc = " << kClaimOccluded << "\n"
            << std::left << std::setw(10) << "Npl x Np" << std::right << std::setw(14) << "processing" << std::setw(14)
            << "sorting" << std::setw(14) << "sorter"
            << "\n";
  for (const Shape& s : shapes) {
    const ManagerCounts c = model_formula_counts({kClaimObjects, kClaimOccluded, s.planes, s.points});
    std::cout << std::left << std::setw(10) << shape_name(s) << std::right << std::setw(14)
              << number(cycles(c.processing, q.cost)) << std::setw(14) << number(cycles(c.sorting, q.cost))
              << std::setw(14) << number(cycles(c.sorter, q.cost)) << "\n";
  }
}

// The verdicts on the seed's claim.
void print_verdicts(const CapacityQuestion& q, const CapacityQuestion& table, const std::vector<Shape>& shapes,
                    const std::set<std::uint32_t>& shape_points) {
  const bool pipelined = q.schedule == UnitSchedule::kPipeline;
  std::cout << "\nverdict on \"about 1000 objects, 60 of them occluded\" at " << number(q.clock_mhz) << " MHz and "
            << number(q.frame_hz) << " Hz, " << costs_text(q.cost) << ", " << (pipelined ? "pipelined" : "in sequence")
            << " (largest No at Noc = 60 in brackets):\n"
            << "  counted model: " << verdict(q, shapes, shape_points) << "\n"
            << "  seed's table:  " << verdict(table, shapes, shape_points) << "\n";
  if (q.pairs == PairTests::kNeighbours) {
    CapacityQuestion all_pairs = q;
    all_pairs.pairs = PairTests::kAll;
    std::cout << "  with the pseudo-code's all-pairs sphere tests (--pairs all, "
              << kClaimObjects * (kClaimObjects - 1) / 2
              << " tests at No = 1000): " << verdict(all_pairs, shapes, shape_points) << "\n";
  }
}

// The options of `cig manager --c.capacity`, checked.
CapacityQuestion capacity_question(const ManagerCommand& c) {
  if (!c.capacity)
    throw InputError("", "--capacity", "cig manager needs --capacity (usage: " + std::string(kUsage) + ")");
  if (!(c.clock_ns > 0 && c.clock_ns <= 1e6))
    throw InputError("", "--clock-ns", "the clock period must be > 0 and <= 1e6 ns, is " + number(c.clock_ns));
  if (!(c.rate_hz > 0 && c.rate_hz <= 1e4))
    throw InputError("", "--rate", "the frame rate must be > 0 and <= 1e4 Hz, is " + number(c.rate_hz));
  CapacityQuestion q;
  q.clock_mhz = 1e3 / c.clock_ns;
  q.frame_hz = c.rate_hz;
  q.cost = parse_cost(c.cost_text);
  q.schedule = c.schedule == "pipeline" ? UnitSchedule::kPipeline : UnitSchedule::kSequence;
  q.pairs = c.pairs == "all" ? PairTests::kAll : PairTests::kNeighbours;
  if (c.occluded.empty()) throw InputError("", "--occluded", "needs at least one number");
  for (long long n : c.occluded)
    if (n < 0 || n > 1000000) throw InputError("", "--occluded", "Noc must lie in 0..1000000, is " + std::to_string(n));
  for (long long n : c.planes)
    if (n < 1 || n > kMaxPlanes) throw InputError("", "--planes", "Npl must lie in 1..4096, is " + std::to_string(n));
  for (long long n : c.points)
    if (n < 3 || n > kMaxPoints) throw InputError("", "--points", "Np must lie in 3..4096, is " + std::to_string(n));
  return q;
}

// The object shapes Npl x Np asked for.
std::vector<Shape> object_shapes(const ManagerCommand& c) {
  std::vector<Shape> shapes;
  if (c.planes.empty() && c.points.empty()) {
    shapes = {{6, 4}, {12, 4}, {24, 4}, {48, 4}, {12, 8}};
  } else {
    const std::vector<long long> pl = c.planes.empty() ? std::vector<long long>{6, 12, 24, 48} : c.planes;
    const std::vector<long long> pt = c.points.empty() ? std::vector<long long>{4} : c.points;
    for (long long p : pt)
      for (long long n : pl) shapes.push_back({std::uint32_t(n), std::uint32_t(p)});
  }
  return shapes;
}

}  // namespace

void ManagerCommand::add_to(CLI::App& app) {
  sub = app.add_subcommand("manager", "seed 000's scene manager as a counted model: operation counts and capacity");
  sub->add_flag("--capacity", capacity, "the largest No per frame for each Noc and Npl x Np, and the seed's claim");
  sub->add_option("--clock-ns", clock_ns, "the clock period in ns (default 10: 100 MHz)");
  sub->add_option("--rate", rate_hz, "frame rate, Hz (default 25)");
  sub->add_option("--cost", cost_text,
                  "cycles per operation by kind, e.g. R=4,L=2,D=8 (kinds R, C, O, L, A, M, D; default 1 each)");
  sub->add_option("--occluded", occluded, "numbers of occluded objects Noc (default 0,20,60,100,200)")->delimiter(',');
  sub->add_option("--planes", planes, "planes per object Npl (with --points: every pair; default 6,12,24,48)")
      ->delimiter(',');
  sub->add_option("--points", points, "points per plane Np (default 4)")->delimiter(',');
  sub->add_option("--schedule", schedule,
                  "sequence: a frame is the three units' sum (default); pipeline: each unit its own frame, the "
                  "slowest one's")
      ->check(CLI::IsMember({"sequence", "pipeline"}));
  sub->add_option("--pairs", pairs,
                  "sphere tests: neighbours in SP, the table's No - 1 (default); all: the pseudo-code's all pairs")
      ->check(CLI::IsMember({"neighbours", "all"}));
}

int ManagerCommand::run() {
  const CapacityQuestion q = capacity_question(*this);
  const std::vector<Shape> shape_list = object_shapes(*this);
  std::set<std::uint32_t> shape_points;
  for (const Shape& s : shape_list) shape_points.insert(s.points);
  print_assumptions(q);
  int checked = 0;
  print_capacity_table(q, occluded, shape_list,
                       "counted model (the table's formulas but for the sorter's R, its L at Noc >= 2 and its C, A, M, "
                       "D at Noc = 0)",
                       checked);
  CapacityQuestion table = q;
  table.source = CountSource::kSeedTable;
  table.pairs = PairTests::kNeighbours;
  print_capacity_table(table, occluded, shape_list, "the seed's table as printed", checked);
  std::cout << "(" << checked << " model entries re-counted by running the three units at No and No + 1)\n";
  print_claim_loads(q, shape_list);
  print_unit_cycles(q, shape_list);
  print_verdicts(q, table, shape_list, shape_points);
  return 0;
}

}  // namespace cig::cli
