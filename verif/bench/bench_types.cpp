// Google Benchmark of the bit-accurate type layer (hls/types): does a kernel written with Int,
// UInt, Fixed, UFixed and the e8m7 code cost more than the same arithmetic written by hand with
// shifts and masks on int64? The computation is the video channel's per-sample step in the
// default (perspective-correct) mode, hls/segment/video_channel.hpp plane_sample:
//   I and W = 1/Z from their planes (F + D i + E j, wrapped to 53 bits), I saturated to [0, 256],
//   the e8m7 code of 1/Z (normalised, rounded to nearest even, saturated), the fog table by that
//   code, and per colour component colour x I then fog (rounded half up, saturated).
//   types/sample/project   the kernel's own code (PlaneFixedArith<PlaneFormatDefault>)
//   types/sample/hand      the same, hand-written on int64 (one line per format step)
// Both run over the same 4096 samples of 64 random planes; before timing, every output of the
// two is compared (a difference is an error: exit status 1). At the end the program prints
// "ratio project/hand=R" (CPU time per sample); R ~ 1 means the types cost nothing.
//   build/bin/bench_types [--benchmark_filter=REGEX]
#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "hls/pixel/attribute_planes.hpp"

namespace {

using namespace cig::hls;
using Plane = PlaneFixedArith<PlaneFormatDefault>;

constexpr int kSamples = 4096;
constexpr int kPlanes = 64;

struct Inputs {
  Plane::Param fi[kPlanes], fw[kPlanes];
  Plane::Gradient di[kPlanes], ei[kPlanes], dw[kPlanes], ew[kPlanes];
  Int<10> w_exponent[kPlanes];
  SampleLevel colour[kPlanes][3], fog[3];
  int plane[kSamples], i[kSamples], j[kSamples];
  FogTable table;
};

// Planes whose I crosses [0, 256] and beyond (saturation both ways) and whose W spans many
// binades (from below 2^-20 of the nearest vertex to the full 2^20, and negative beyond the
// horizon), at samples anywhere on the largest lattice.
const Inputs& inputs() {
  static const Inputs* in = [] {
    auto* p = new Inputs;
    std::mt19937_64 rng(14);
    auto uniform = [&](std::int64_t lo, std::int64_t hi) {
      return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng);
    };
    for (int k = 0; k < kPlanes; ++k) {
      p->fi[k] = Plane::Param(uniform(-(std::int64_t{64} << 16), std::int64_t{320} << 16));
      p->di[k] = Plane::Gradient(uniform(-(1 << 14), 1 << 14));
      p->ei[k] = Plane::Gradient(uniform(-(1 << 14), 1 << 14));
      p->fw[k] = Plane::Param(uniform(-(std::int64_t{1} << 30), std::int64_t{1} << 36));
      p->dw[k] = Plane::Gradient(uniform(-(1 << 22), 1 << 22));
      p->ew[k] = Plane::Gradient(uniform(-(1 << 22), 1 << 22));
      p->w_exponent[k] = Int<10>(uniform(-160, 100));
      for (int c = 0; c < 3; ++c) p->colour[k][c] = SampleLevel(uniform(0, 255));
    }
    for (int c = 0; c < 3; ++c) p->fog[c] = SampleLevel(uniform(0, 255));
    for (int s = 0; s < kSamples; ++s) {
      p->plane[s] = int(uniform(0, kPlanes - 1));
      p->i[s] = int(uniform(0, kMaxLatticeSize - 1));
      p->j[s] = int(uniform(0, kMaxLatticeSize - 1));
    }
    for (int c = 0; c < kFogTableSize; ++c) p->table.f[c] = FogFactor::from_raw_value(std::uint64_t(uniform(0, 256)));
    return p;
  }();
  return *in;
}

// The kernel's code, as plane_sample runs it.
void project_samples(const Inputs& in, std::uint16_t* out) {
  for (int s = 0; s < kSamples; ++s) {
    const int k = in.plane[s];
    const Plane::Param vi = Plane::at_sample(in.fi[k], in.di[k], in.ei[k], in.i[s], in.j[s]);
    const Plane::Param vw = Plane::at_sample(in.fw[k], in.dw[k], in.ew[k], in.i[s], in.j[s]);
    const Plane::Intensity level = Plane::intensity(vi);
    const FogFactor f = Plane::fog_factor(in.table, vw, in.w_exponent[k]);
    for (int c = 0; c < 3; ++c)
      out[3 * s + c] = std::uint16_t(Plane::sample_colour(in.colour[k][c], level, f, in.fog[c]).raw().value());
  }
}

// The e8m7 code of s * 2^(e - 127 - 7 - 12), by hand (zfloat_from_aligned).
inline std::uint32_t hand_zfloat(int e, std::int64_t s) {
  if (s <= 0) return 0;
  const int msb = 63 - __builtin_clzll(std::uint64_t(s));
  int exp = e + msb - 19;
  std::uint64_t sig;
  if (msb <= 7) {
    sig = std::uint64_t(s) << (7 - msb);
  } else {
    const int drop = msb - 7;
    const std::uint64_t floor_sig = std::uint64_t(s) >> drop;
    const std::uint64_t rem = std::uint64_t(s) & ((std::uint64_t{1} << drop) - 1);
    const std::uint64_t half = std::uint64_t{1} << (drop - 1);
    sig = floor_sig + ((rem > half || (rem == half && (floor_sig & 1))) ? 1 : 0);
    if (sig & 256) {
      sig = 128;
      exp += 1;
    }
  }
  if (exp < 0) return 0;
  if (exp > 255) return 0x7FFF;
  return std::uint32_t(exp) << 7 | std::uint32_t(sig & 127);
}

// The same arithmetic on int64, the formats in the comments (G = 16 fractional bits).
void hand_samples(const Inputs& in, std::uint16_t* out) {
  for (int s = 0; s < kSamples; ++s) {
    const int k = in.plane[s];
    const std::int64_t i = in.i[s], j = in.j[s];
    // F + D i + E j wrapped to 53 bits
    const std::int64_t vi =
        std::int64_t(std::uint64_t(in.fi[k].value() + in.di[k].value() * i + in.ei[k].value() * j) << 11) >> 11;
    const std::int64_t vw =
        std::int64_t(std::uint64_t(in.fw[k].value() + in.dw[k].value() * i + in.ew[k].value() * j) << 11) >> 11;
    const std::int64_t level = vi < 0 ? 0 : vi > (std::int64_t{256} << 16) ? std::int64_t{256} << 16 : vi;  // [0, 256]
    const std::int64_t sw = vw > (std::int64_t{1} << 41) - 1 ? (std::int64_t{1} << 41) - 1 : vw;
    const std::int64_t f = std::int64_t(in.table.f[hand_zfloat(int(in.w_exponent[k].value()) + 130, sw)].raw().value());
    for (int c = 0; c < 3; ++c) {
      std::int64_t shaded = (std::int64_t(in.colour[k][c].value()) * level + (1 << 15)) >> 16;  // 8 fraction bits
      shaded = shaded > 0xFFFF ? 0xFFFF : shaded;
      std::int64_t mixed = (shaded * (256 - f) + (std::int64_t(in.fog[c].value()) * f << 8) + 128) >> 8;
      mixed = mixed < 0 ? 0 : mixed > 0xFFFF ? 0xFFFF : mixed;
      out[3 * s + c] = std::uint16_t(mixed);
    }
  }
}

bool outputs_equal() {
  static std::vector<std::uint16_t> a(3 * kSamples), b(3 * kSamples);
  project_samples(inputs(), a.data());
  hand_samples(inputs(), b.data());
  return a == b;
}

void run(benchmark::State& state, void (*samples)(const Inputs&, std::uint16_t*)) {
  if (!outputs_equal()) {
    state.SkipWithError("the project's types and the hand-written code disagree");
    return;
  }
  const Inputs& in = inputs();
  std::vector<std::uint16_t> out(3 * kSamples);
  for (auto _ : state) {
    benchmark::DoNotOptimize(&in);
    samples(in, out.data());
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.counters["samples/s"] =
      benchmark::Counter(double(kSamples) * double(state.iterations()), benchmark::Counter::kIsRate);
}

// Console output plus the CPU time per iteration of each case, for the ratio.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  std::map<std::string, double> cpu;
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs)
      if (!r.error_occurred && r.iterations > 0) cpu[r.benchmark_name()] = r.GetAdjustedCPUTime();
  }
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::RegisterBenchmark("types/sample/project", run, project_samples);
  benchmark::RegisterBenchmark("types/sample/hand", run, hand_samples);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  if (!outputs_equal()) {
    std::printf("the project's types and the hand-written code disagree\n");
    return 1;
  }
  const auto p = reporter.cpu.find("types/sample/project"), h = reporter.cpu.find("types/sample/hand");
  if (p != reporter.cpu.end() && h != reporter.cpu.end() && h->second > 0)
    std::printf("ratio project/hand=%.3f\n", p->second / h->second);
  return 0;
}
