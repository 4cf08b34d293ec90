// Lock-step co-simulation of the quadtree RTL (rtl/quadtree/qt_raster.sv, Verilated) against the
// bit-accurate kernels driven by the cycle-level architecture model (cmodel/quadtree/
// arch_model.hpp): the same stream of level-0 windows (the setup kernel's output) goes through
// both, with the same input gaps and output stalls, and every record is compared:
//   * per PE: every window it loads (cycle, mask word, the record) and every child it emits
//     (cycle, child number, full flag, the record: level, address, d per edge, f per parameter,
//     the polygon's constants, the pixel level's sub-pixel mask);
//   * per pixel processor: every record it takes (cycle, record, samples taken, became full);
//   * the mask set requests of every cycle (as a set: their order within a cycle is immaterial);
//   * the frame's cycle count and the final pixels (the RTL's read-out port against the model's
//     resolve).
// Records are compared as bit vectors in the RTL's layout (record_bits.hpp); the first mismatch
// is reported with the stream, the record number, the cycle, the field, the expected and the
// obtained value.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "engine/engine.hpp"
#include "image/image.hpp"
#include "quadtree/arch_model.hpp"
#include "quadtree/quadtree_frame.hpp"
#include "record_bits.hpp"
#include "trace_settings.hpp"

namespace cig::cosim {

// The format the RTL implements (rtl/quadtree/README.md parameters PW, GW, G) and its record
// layout.
using RtlArith = hls::QuadFixedArith<hls::QuadFormatFine>;
using RtlLayout = RecordLayout<RtlArith>;
inline RtlLayout rtl_layout() { return RtlLayout(); }

// The run's settings both sides take: the verification stalls and the architecture option
// ArchConfig::start_window (the RTL's input start_window_i).
struct StallConfig {
  std::uint32_t seed = 1;
  int input_gap_percent = 0;
  int output_stall_percent = 0;
  bool start_window = false;
};

enum class EventKind { kLoad, kEmit, kPixel };

struct Event {
  EventKind kind = EventKind::kLoad;
  long long cycle = 0;
  int child = 0;      // emits
  unsigned mask = 0;  // loads: the mask word; pixels: the samples taken
  bool full = false;  // emits: child fully covered; pixels: the pixel became full
  Bits record;
};

struct MaskSetEvent {
  long long cycle;
  int level, x, y, child;
  bool operator<(const MaskSetEvent& o) const {
    return std::tie(cycle, level, x, y, child) < std::tie(o.cycle, o.level, o.x, o.y, o.child);
  }
  bool operator==(const MaskSetEvent& o) const {
    return std::tie(cycle, level, x, y, child) == std::tie(o.cycle, o.level, o.x, o.y, o.child);
  }
};

struct Trace {
  long long cycles = 0;
  std::vector<std::vector<Event>> pe;     // per PE: loads and emits in cycle order
  std::vector<std::vector<Event>> pixel;  // per pixel processor
  std::vector<MaskSetEvent> mask_sets;    // sorted
  Image image;
  double seconds = 0;        // wall time of the run (simulation speed)
  bool busy_at_cut = false;  // RtlRunner::run_cut: the design still held work when it stopped
};

// The model's side: the architecture model with a tracer that records what the RTL must show.
template <class P>
class TraceRecorder final : public quad::ArchTracer<P> {
 public:
  TraceRecorder(const RecordLayout<P>& L, Trace& t, int pes, int pixel_units) : L_(L), t_(t) {
    t_.pe.assign(std::size_t(pes), {});
    t_.pixel.assign(std::size_t(pixel_units), {});
  }
  // A load is compared by its cycle and mask word: the window it takes is the head of the PE's
  // input FIFO, i.e. a record already compared where it was emitted (or the input stream's).
  void load(long long cycle, int pe, const quad::QuadItem<P>&, unsigned mask) override {
    t_.pe[std::size_t(pe)].push_back({EventKind::kLoad, cycle, 0, mask, false, Bits()});
  }
  void emit(long long cycle, int pe, int child, const quad::QuadItem<P>& c, bool full) override {
    t_.pe[std::size_t(pe)].push_back(
        {EventKind::kEmit, cycle, child, 0, full, pack_record(L_, c.w, unsigned(c.samples.value()))});
  }
  void pixel(long long cycle, int unit, const quad::QuadItem<P>& r, std::uint64_t fresh, bool full) override {
    t_.pixel[std::size_t(unit)].push_back(
        {EventKind::kPixel, cycle, 0, unsigned(fresh), full, pack_record(L_, r.w, unsigned(r.samples.value()))});
  }
  void mask_set(long long cycle, int level, int x, int y, int child) override {
    t_.mask_sets.push_back({cycle, level, x, y, child});
  }

 private:
  const RecordLayout<P>& L_;
  Trace& t_;
};

// Runs the model on `roots` with the pixel frame `pixels` (begun for the frame).
Trace model_trace(const quad::Architecture& arch, const std::vector<hls::QuadWindow<RtlArith>>& roots,
                  quad::PixelFrame<RtlArith>& pixels, const StallConfig& stalls, int fifo_depth,
                  quad::ArchStats* stats = nullptr);

struct Comparison {
  long long records_compared = 0;  // PE loads and emits, pixel records, mask sets, pixels
  long long mismatches = 0;        // records that differ (or are missing on one side)
  bool cycles_equal = false;
  std::string first;  // the first mismatch, in detail ("" if none)
  bool ok() const { return mismatches == 0 && cycles_equal; }
};

Comparison compare_traces(const RtlLayout& L, const Trace& model, const Trace& rtl, bool compare_cycles = true);

// The Verilated configurations this build has (N_LOG2, TREE_LEVELS), and a runner for any of them.
struct RtlConfig {
  int raster_log2;
  int tree_levels;
  std::string arch_text() const;  // "9p", "7p2t", ...
};
std::vector<RtlConfig> rtl_configs();

// What a Verilated configuration was elaborated with: the public parameters of its wrapper
// (qt_raster_cosim_tb.sv), i.e. rtl/quadtree/qt_pkg.sv's layout and unit counts as the RTL computed
// them.
struct RtlModelParams {
  int ne, np, ew, aw, pw, gw, g;  // record widths (qt_raster NE .. G)
  int win_w, pix_w, mask_set_w;   // record and mask set request widths
  int npe, npix;                  // PEs, pixel processors
  // Entries of the light-cover table: one per pixel that a light point touches; a frame with more
  // lit pixels cannot be co-simulated.
  int light_covers;
};

class RtlRunner {
 public:
  virtual ~RtlRunner() = default;
  // What this configuration was elaborated with.
  virtual const RtlModelParams& params() const = 0;
  // Runs one frame through the RTL: configuration from `pixels` (fog table, colours, light
  // covers), frame start, the stream with the stalls, the read-out of every pixel.
  virtual Trace run(const std::vector<hls::QuadWindow<RtlArith>>& roots, const quad::PixelFrame<RtlArith>& pixels,
                    const StallConfig& stalls, long long max_cycles) = 0;
  // A frame cut short (a frame overrun, rtl/quadtree/README.md "Frame"): configuration, frame
  // start, the stream with the stalls for `cycles` cycles, then `hold` more cycles with no input
  // and every pixel processor stalled (the records back up: FIFOs fill, PEs stall), and it returns
  // without draining the frame or reading it out; the next run's frame start must clear what is
  // left. The trace holds the events of the first `cycles` cycles, no image.
  virtual Trace run_cut(const std::vector<hls::QuadWindow<RtlArith>>& roots, const quad::PixelFrame<RtlArith>& pixels,
                        const StallConfig& stalls, long long cycles, int hold) = 0;
  // FST waveform of the next run (this build must have tracing on): the cycles and scopes the
  // settings name (trace_settings.hpp), the file closed when that run ends.
  virtual void trace_to(const TraceSettings& trace) = 0;
  void trace_to(const std::string& fst_file) { trace_to(TraceSettings{fst_file}); }
  // Called every kProgressCycles cycles of a run with the cycle reached ({}: none).
  void on_cycles(std::function<void(long long)> f) { on_cycles_ = std::move(f); }

 protected:
  std::function<void(long long)> on_cycles_;
};
// nullptr when this build has no such configuration.
std::unique_ptr<RtlRunner> make_rtl_runner(int raster_log2, int tree_levels);
// The benchmark's models of the same RTL, Verilated for speed (9p and 7p2t; no tracing: trace_to
// throws); nullptr for the other configurations. In the library cig_cosim_fast (bench_rtl).
std::unique_ptr<RtlRunner> make_fast_rtl_runner(int raster_log2, int tree_levels);

// One frame through both sides: the model first, then the RTL (its progress: the cycles done and
// the model's count; before_rtl: called with the model's count before the RTL starts, where a
// trace is planned against the frame's cycles).
struct CosimResult {
  Trace model, rtl;
  Comparison comparison;
  quad::ArchStats stats;
};
using CycleProgress = std::function<void(long long done, long long total)>;
using BeforeRtl = std::function<void(long long model_cycles)>;
CosimResult cosim_frame(const ScreenFrame& frame, RtlRunner& rtl, const RtlConfig& cfg, const StallConfig& stalls,
                        long long max_cycles = 200000000, const CycleProgress& progress = {},
                        const BeforeRtl& before_rtl = {});
// The same on a stream of windows already set up (tests build their own streams).
CosimResult cosim_stream(const ScreenFrame& frame_for_tables, const std::vector<hls::QuadWindow<RtlArith>>& roots,
                         RtlRunner& rtl, const RtlConfig& cfg, const StallConfig& stalls,
                         long long max_cycles = 200000000, const CycleProgress& progress = {},
                         const BeforeRtl& before_rtl = {});

// The quadtree engine of `cig render|raster --engine quadtree --arch A` with the co-simulation's
// settings (the RTL's format, 16 samples, masks on, FIFO depth 2, the start window, the fan split
// on or off), and the stream it runs from a frame: its own first step (RasterEngine::engine_frame:
// the fan split of non-planar polygons, the formatter grid), its capacities checked (InputError).
std::unique_ptr<RasterEngine> quadtree_engine(const RtlConfig& cfg, const StallConfig& stalls, bool fan_split);
struct EngineStream {
  ScreenFrame frame;  // the frame the engine rasterises
  bool fan_split = true;
  long polygons_split = 0, triangles_added = 0;
};
EngineStream engine_stream(const RasterEngine& engine, const ScreenFrame& frame);

}  // namespace cig::cosim
