// cig arch --processor invparam: seed 002's inverse-parameter visibility processor (SPEC F), the
// frame time and faces per second of its systolic array (cmodel/invparam/systolic_array.hpp):
//   full streaming     every column gets every object's tokens: the seed's formula
//                      t = (max(N_K, ceil(N_n/4)*4) (P - 1) + N_K + N_n + 3) t_t, N_K = 4((m+1)n+1),
//                      which the cycle model reproduces exactly (verif/unit/test_invparam_array.cpp);
//   covered columns    an object's tokens go only to the columns its screen extent covers (mean
//                      width w): the closed form with n w / P objects a column, exact against the
//                      cycle model when that is an integer; the limit for n -> infinity is
//                      m / (4 (m + 1) w t_t).
// The seed's claim beside: > 1.6 M faces/s for objects of mean projected width <= 50 px.
#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "cli/arch_command.hpp"
#include "common/error.hpp"
#include "invparam/systolic_array.hpp"

namespace cig::cli {

namespace {

constexpr double kSeedClaimFacesPerS = 1.6e6;  // seed 002: "more than 1,600,000 faces/s"
constexpr double kSeedClaimWidth = 50;         // "for objects of mean projected width <= 50 px"

using nlohmann::ordered_json;

void print_full(const ArchCommand& c, ordered_json& report) {
  std::printf("Full streaming (every column gets every object): the seed's formula, = the cycle model's count\n");
  std::printf("%10s %12s %16s %12s %14s\n", "n", "N_K", "clocks", "frame ms", "faces/s");
  ordered_json rows = ordered_json::array();
  for (long long n : c.objects) {
    const invparam::Throughput t =
        invparam::invparam_throughput(c.faces_per_object, double(n), c.columns, c.pps, c.columns, c.clock_ns * 1e-9);
    const long long nk = invparam::chain_codes(c.faces_per_object, n);
    const long long clocks = invparam::seed_frame_clocks(c.faces_per_object, n, c.pps, c.columns);
    std::printf("%10lld %12lld %16lld %12.3f %14.0f\n", n, nk, clocks, t.full_seconds * 1e3, t.full_faces_per_s);
    rows.push_back({{"n", n},
                    {"n_k", nk},
                    {"clocks", clocks},
                    {"frame_ms", t.full_seconds * 1e3},
                    {"faces_per_s", t.full_faces_per_s}});
  }
  report["full"] = rows;
}

void print_covered(const ArchCommand& c, ordered_json& report) {
  std::printf("\nCovered columns (an object's tokens only to the columns it covers; n w / P objects a column)\n");
  std::printf("%8s %10s %14s %16s %12s %14s %16s\n", "width", "n", "N_K a column", "clocks", "frame ms", "faces/s",
              "limit n->inf");
  ordered_json rows = ordered_json::array();
  for (double w : c.widths)
    for (long long n : c.objects) {
      const invparam::Throughput t =
          invparam::invparam_throughput(c.faces_per_object, double(n), w, c.pps, c.columns, c.clock_ns * 1e-9);
      const double nk = 4 * ((c.faces_per_object + 1) * double(n) * w / c.columns + 1);
      std::printf("%8g %10lld %14.1f %16.0f %12.3f %14.0f %16.0f\n", w, n, nk, t.covered_clocks,
                  t.covered_seconds * 1e3, t.covered_faces_per_s, t.covered_limit_faces_per_s);
      rows.push_back({{"width", w},
                      {"n", n},
                      {"n_k_per_column", nk},
                      {"clocks", t.covered_clocks},
                      {"frame_ms", t.covered_seconds * 1e3},
                      {"faces_per_s", t.covered_faces_per_s},
                      {"limit_faces_per_s", t.covered_limit_faces_per_s}});
    }
  report["covered_columns"] = rows;
}

}  // namespace

// Every option checked before any output.
void ArchCommand::check_invparam_options() {
  for (const char* o : {"--n", "--raster", "--perf-n", "--aspects", "--areas", "--positions", "--archs", "--stream",
                        "--perf-aspect", "--perf-rotation", "--fifo", "--seed", "--threads", "--table"})
    if (sub->count(o) > 0) throw InputError("", o, "is a quadtree option; --processor invparam takes none");
  if (faces_per_object < 1 || faces_per_object > 1000000)
    throw InputError("", "--faces-per-object", "m must be 1..1000000, not " + std::to_string(faces_per_object));
  if (columns < 1 || columns > 65536)
    throw InputError("", "--columns", "P must be 1..65536, not " + std::to_string(columns));
  if (pps < 1 || pps > 65536) throw InputError("", "--pps", "N_n must be 1..65536, not " + std::to_string(pps));
  if (!(clock_ns > 0) || !(clock_ns <= 1e6))
    throw InputError("", "--clock-ns", "t_t must be a number of ns, > 0 and <= 1e6");
  if (objects.empty()) throw InputError("", "--objects", "needs at least one object count");
  for (long long n : objects)
    if (n < 1 || n > 1000000000LL)
      throw InputError("", "--objects", "n must be 1..1000000000, not " + std::to_string(n));
  if (widths.empty()) throw InputError("", "--widths", "needs at least one width");
  for (double w : widths)
    if (!(w > 0) || !(w <= columns))
      throw InputError("", "--widths",
                       "a mean object width must be > 0 and <= P = " + std::to_string(columns) + " columns");
  if (!report_file.empty()) check_output_file(report_file, "--report");
}

int ArchCommand::run_invparam() {
  check_invparam_options();
  std::printf("== Seed 002's inverse-parameter visibility processor: frame time and faces/s ==\n");
  std::printf("m = %d faces per object, P = %d columns, N_n = %d PPs, t_t = %g ns\n", faces_per_object, columns, pps,
              clock_ns);
  std::printf("The seed's claim: > %.1f M faces/s for objects of mean projected width <= %g px\n\n",
              kSeedClaimFacesPerS / 1e6, kSeedClaimWidth);
  ordered_json report;
  report["command"] = "arch";
  report["processor"] = "invparam";
  report["m"] = faces_per_object;
  report["columns"] = columns;
  report["pps"] = pps;
  report["clock_ns"] = clock_ns;
  report["seed_claim_faces_per_s"] = kSeedClaimFacesPerS;
  report["seed_claim_width"] = kSeedClaimWidth;
  print_full(*this, report);
  print_covered(*this, report);
  const double limit =
      invparam::invparam_throughput(faces_per_object, 1, kSeedClaimWidth, pps, columns, clock_ns * 1e-9)
          .covered_limit_faces_per_s;
  std::printf("\nAt width %g: covered columns tend to %.0f faces/s (the seed: > %.0f); full streaming to %.0f.\n",
              kSeedClaimWidth, limit, kSeedClaimFacesPerS,
              faces_per_object / (4.0 * (faces_per_object + 1) * columns * clock_ns * 1e-9));
  report["limit_at_claim_width_faces_per_s"] = limit;
  if (!report_file.empty()) write_text_file(report_file, report_text(report));
  return 0;
}

}  // namespace cig::cli
