// Cycle-level model of a recursive-subdivision raster processor (seed 004) for any architecture of
// eq. 1 (architecture.hpp). It drives the bit-accurate kernels (hls/quadtree: PE, mask memory; the
// pixel processor through a PixelSink) clock by clock, so its windows, pixels, mask updates and
// cycle counts are exactly what the RTL (rtl/quadtree/) must produce: verif/cosim/quadtree compares
// them record by record and cycle by cycle. The micro-architecture it defines:
//
// PE (one sub-window per clock). A PE holds one window and a 4-bit list of children still to do.
//   * Load: when it holds no window (or finishes one this cycle) it takes the next window, from
//     its LIFO first (stacks), else from the head of its input FIFO, reads the window's mask word
//     and drops the masked children from the list (the mask check costs no cycle). A window whose
//     four children are all masked is dropped at once.
//   * Each cycle it evaluates the lowest child still to do (coverage, full coverage, parameters,
//     pixel mask: hls/quadtree/pe.hpp). A child that is not covered costs the cycle. A covered
//     child goes to the stage's output (the next stage's input FIFO, the quadrant's PE in a tree,
//     or the pixel processor's FIFO) if that FIFO had room at the start of the cycle, else the PE
//     stalls and retries the same child next cycle; in a stack a child of a level the stack also
//     does goes to its LIFO (no stall). When an opaque polygon covers the accepted child fully,
//     the PE sets the child's mask bit.
//   So a window with k unmasked children takes k cycles when nothing stalls: t_e = 1 clock per
//   sub-window test (all edges in parallel), t_p = 0 (the parameter adders work in parallel with
//   the test): eq. 5 becomes t_i = 4 w_(i-1) clocks less the masked children.
// FIFOs: depth `fifo_depth` (default 2). A push made in cycle t is visible to the consumer from
//   cycle t + 1; a producer sees the count at the start of the cycle (a pop in the same cycle does
//   not make room until the next), so FIFO ready is a register.
// Pixel processor: one record per clock from its FIFO (a tree's leaf PEs each have their own, as
//   the frame memory is interleaved by quadrant); when a pixel's samples become all owned it sets
//   the pixel's bit in the level n-1 mask.
// Masks: reads see the state at the start of the cycle; the cycle's sets and their upward closure
//   take effect at the clock edge (hls/quadtree/mask_memory.hpp).
// Input port: one polygon piece (its level-0 window from the setup) per clock into the first
//   stage's FIFO when it has room.
// Stalls for verification: `input_gap_percent` of the cycles the input port offers nothing,
//   `output_stall_percent` of the cycles a pixel processor takes nothing, chosen by
//   stall_hit(seed, cycle, stream) which the co-simulation harness applies to the RTL too.
//
// Because every PE handles its windows in FIFO order, every pixel's records reach its pixel
// processor in polygon order, whatever the architecture or the stalls; masks only remove work, so
// the image never depends on timing (the counts of windows tested do).
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include "common/stall_pattern.hpp"
#include "hls/quadtree/mask_memory.hpp"
#include "hls/quadtree/pe.hpp"
#include "quadtree/architecture.hpp"

namespace cig::quad {

using cig::stall_hit;  // the verification stall pattern (common/stall_pattern.hpp)

struct ArchConfig {
  int fifo_depth = 2;
  bool masks = true;
  std::uint32_t stall_seed = 1;
  int input_gap_percent = 0;              // verification: cycles the input port is empty
  int output_stall_percent = 0;           // verification: cycles a pixel processor is not ready
  int side_log2 = hls::kDefaultSideLog2;  // S = 2^t samples a side per pixel (the RTL: 4 x 4)
  // A polygon piece starts its subdivision at its start window (hls QuadPolygon::start_level):
  // a PE loading a window above that level keeps only the child on the path to it (the others
  // hold no sample of the piece and are skipped like masked ones, at no cycle). Off: the seed's
  // start at the whole screen. The windows still pass every level in FIFO order (polygon order
  // at every pixel processor) and are computed by the same subdivision: the image is the same.
  bool start_window = false;
};

// The children of window w a PE tests: all four, or, with ArchConfig::start_window and w above
// the piece's start window, only the one on the path to it (q = 2 y_b + x_b).
template <class P>
unsigned start_window_children(const hls::QuadWindow<P>& w, bool start_window) {
  const int level = int(w.level.value()), start = int(w.poly.start_level.value());
  if (!start_window || level >= start) return 0xFu;
  const int sh = start - level - 1;  // the child's address bit of the start window
  const unsigned xb = (unsigned(w.poly.start_x.value()) >> sh) & 1u, yb = (unsigned(w.poly.start_y.value()) >> sh) & 1u;
  return 1u << (2 * yb + xb);
}

// What flows through the FIFOs: a window (or a pixel record: a level-n window and its samples).
template <class P>
struct QuadItem {
  hls::QuadWindow<P> w;
  hls::PixelSampleMask samples;  // pixel records: the covered samples (bit S dj + di)
  std::uint32_t piece = 0;       // index of the polygon piece in the input stream
};

struct LevelStats {
  long long tested = 0;             // children of this level evaluated
  long long covered = 0;            // children of this level emitted (w_l)
  long long masked = 0;             // children of this level skipped by their mask bit
  long long full_opaque = 0;        // children of this level fully covered by an opaque polygon
  long long loaded = 0;             // windows of this level a PE took
  long long loaded_all_masked = 0;  // ... of which all four children were masked
  long long outside_start = 0;      // children of this level skipped off the path to the start window
};

struct PieceStats {
  int deepest_level = 0;  // deepest level of any emitted window (0: only its root)
  bool met_mask = false;  // some child (or the root's word) was masked
  long long pixel_records = 0;
  long long accepted_cycle = -1, last_cycle = -1;
};

struct ArchStats {
  long long cycles = 0;
  std::vector<LevelStats> level;           // 0..n
  std::vector<long long> pe_busy_cycles;   // cycles a PE evaluated a child (stalls excluded)
  std::vector<long long> pe_stall_cycles;  // cycles a PE held a covered child its output could not take
  long long pixel_records = 0, pixels_full = 0, mask_sets = 0, mask_words_full = 0;
  long long input_wait_cycles = 0;  // cycles the input had a piece but the first FIFO was full
  std::vector<PieceStats> pieces;
};

// The pixel processor's datapath, provided by the engine (or the co-simulation harness).
template <class P>
class PixelSink {
 public:
  virtual ~PixelSink() = default;
  // The frame's polygon pieces (their level-0 windows), given before the first record and kept
  // until the run's end: every record's polygon constants are its piece's (QuadItem::piece), so a
  // sink may read them there by reference instead of copying them from the record.
  virtual void pieces(const std::vector<hls::QuadWindow<P>>& /*roots*/) {}
  // Processes one pixel record; returns the samples it took, and sets `became_full` when the
  // pixel's samples just became all owned.
  virtual std::uint64_t pixel(int unit, const QuadItem<P>& item, bool& became_full) = 0;
};

// Optional observer of every record (co-simulation, tests).
template <class P>
class ArchTracer {
 public:
  virtual ~ArchTracer() = default;
  virtual void load(long long /*cycle*/, int /*pe*/, const QuadItem<P>& /*window*/, unsigned /*mask*/) {}
  virtual void emit(long long /*cycle*/, int /*pe*/, int /*child*/, const QuadItem<P>& /*child*/, bool /*full*/) {}
  virtual void pixel(long long /*cycle*/, int /*unit*/, const QuadItem<P>& /*record*/, std::uint64_t /*fresh*/,
                     bool /*became_full*/) {}
  virtual void mask_set(long long /*cycle*/, int /*level*/, int /*x*/, int /*y*/, int /*child*/) {}
};

template <class P>
class ArchModel {
 public:
  ArchModel(const Architecture& arch, const ArchConfig& cfg) : arch_(arch), cfg_(cfg), n_(arch.raster_log2) { build(); }

  // Runs one frame: the pieces' level-0 windows in priority order. `masks` must be cleared by the
  // caller for a new frame (hls::mask_clear).
  ArchStats run(const std::vector<hls::QuadWindow<P>>& roots, hls::MaskMemory& masks, PixelSink<P>& sink,
                ArchTracer<P>* tracer = nullptr) {
    ArchStats st;
    st.level.assign(std::size_t(n_) + 1, LevelStats());
    st.pe_busy_cycles.assign(pes_.size(), 0);
    st.pe_stall_cycles.assign(pes_.size(), 0);
    st.pieces.assign(roots.size(), PieceStats());
    reset();
    sink.pieces(roots);
    std::size_t next_root = 0;
    long long t = 0;
    for (;;) {
      // Input port.
      if (next_root < roots.size()) {
        if (!stall_hit(cfg_.stall_seed, std::uint64_t(t), 0, cfg_.input_gap_percent)) {
          Fifo& f = fifos_[std::size_t(pes_[0].in_fifo)];
          if (f.start_count() < cfg_.fifo_depth) {
            const int slot = allocate();
            pool_[std::size_t(slot)].w = roots[next_root];
            pool_[std::size_t(slot)].samples = hls::PixelSampleMask(0);
            pool_[std::size_t(slot)].piece = std::uint32_t(next_root);
            st.pieces[next_root].accepted_cycle = t;
            push(pes_[0].in_fifo, slot);
            ++next_root;
          } else {
            ++st.input_wait_cycles;
          }
        }
      }
      // PEs and pixel processors, all reading the state at the start of the cycle (only the clock
      // edge, commit, changes the active lists).
      for (int p : active_pes_)
        if (pes_[std::size_t(p)].asleep_since < 0) step_pe(p, t, masks, st, tracer);
      for (int u : active_pixels_) step_pixel(u, t, sink, st, tracer);
      // The clock edge.
      commit(t, masks, st, tracer);
      ++t;
      if (next_root >= roots.size() && in_flight_ == 0) break;
    }
    // At least one cycle: the one in which the frame starts (an empty frame is idle at the next
    // edge), as the RTL counts it (verif/cosim/quadtree/rtl_runner.cpp).
    st.cycles = t;
    return st;
  }

  const Architecture& architecture() const { return arch_; }
  int pe_count() const { return int(pes_.size()); }
  int pixel_units() const { return pixel_units_; }
  // The first and last level of PE p (for reports).
  int pe_first_level(int p) const { return pes_[std::size_t(p)].first_level; }
  int pe_last_level(int p) const { return pes_[std::size_t(p)].last_level; }
  int pe_stage(int p) const { return pes_[std::size_t(p)].stage; }

 private:
  struct Fifo {
    std::vector<int> buf;  // ring of item slots, allocated on first push
    int head = 0, count = 0;
    bool popped = false;  // this cycle
    int producers = 0;    // PEs that may push into it
    int sleeper = -1;     // the PE asleep on it (see Pe::asleep_since)
    int start_count() const { return count + (popped ? 1 : 0); }
  };
  struct Work {
    int slot = -1;          // the window held (an item slot)
    std::vector<int> lifo;  // stacks: pending windows (item slots)
    // Model-speed device, not hardware: the evaluation of the child the PE offers while its output
    // is full. The hardware re-evaluates it every stalled cycle; evaluate_child depends only on the
    // held window and the child's number, so the kept result is what it would compute. Kept
    // exactly while the child stalls: then stalled_on names its full output FIFO, else it is -1.
    hls::QuadChild<P> child;
    int stalled_on = -1;
  };
  struct Pe {
    int stage = 0;
    int first_level = 1, last_level = 1;  // levels of the children it produces
    int in_fifo = 0;
    int out_base = 0;  // FIFO index (or pixel FIFO index) of child 0
    bool out_by_quadrant = false;
    bool out_pixel = false;
    bool busy = false;
    unsigned todo = 0;
    bool active = false;
    // Model-speed device, not hardware: a PE stalled on an output FIFO it alone fills stays
    // stalled until that FIFO is popped (the FIFO only drains meanwhile), so it is not stepped:
    // from cycle asleep_since + 1 until the clock edge of the first pop, whose commit counts the
    // skipped cycles as the stall cycles they are (-1: awake).
    long long asleep_since = -1;
    std::unique_ptr<Work> work;
  };

  void build() {
    int fifo = 0;
    std::vector<int> stage_first_pe;
    for (std::size_t s = 0; s < arch_.stages.size(); ++s) {
      const ArchStage& st = arch_.stages[s];
      stage_first_pe.push_back(int(pes_.size()));
      const int depths = st.kind == 't' ? st.levels() : 1;
      for (int k = 0; k < depths; ++k) {
        const long long count = st.kind == 't' ? (1LL << (2 * k)) : 1;
        for (long long m = 0; m < count; ++m) {
          Pe pe;
          pe.stage = int(s);
          pe.first_level = st.kind == 't' ? st.first_level + k : st.first_level;
          pe.last_level = st.kind == 't' ? st.first_level + k : st.last_level;
          pe.in_fifo = fifo++;
          pes_.push_back(std::move(pe));
        }
      }
    }
    // Outputs.
    const ArchStage& last = arch_.stages.back();
    pixel_units_ = int(arch_.pixel_processors());
    pixel_fifo_base_ = fifo;
    fifos_.resize(std::size_t(fifo + pixel_units_));
    for (std::size_t s = 0; s < arch_.stages.size(); ++s) {
      const ArchStage& st = arch_.stages[s];
      const int first = stage_first_pe[s];
      if (st.kind != 't') {
        Pe& pe = pes_[std::size_t(first)];
        if (st.last_level == n_) {
          pe.out_pixel = true;
          pe.out_base = pixel_fifo_base_;
        } else {
          pe.out_base = pes_[std::size_t(stage_first_pe[s + 1])].in_fifo;
        }
        continue;
      }
      // Tree: depth k has 4^k PEs starting at first + (4^k - 1) / 3.
      for (int k = 0; k < st.levels(); ++k) {
        const long long base = first + ((1LL << (2 * k)) - 1) / 3;
        const long long next_base = first + ((1LL << (2 * (k + 1))) - 1) / 3;
        for (long long m = 0; m < (1LL << (2 * k)); ++m) {
          Pe& pe = pes_[std::size_t(base + m)];
          if (k + 1 < st.levels()) {
            pe.out_by_quadrant = true;
            pe.out_base = pes_[std::size_t(next_base + 4 * m)].in_fifo;
          } else {
            pe.out_pixel = true;
            pe.out_base = pixel_fifo_base_ + int(m);
          }
        }
      }
    }
    (void)last;
    for (const Pe& pe : pes_)
      for (int q = 0; q < (pe.out_by_quadrant ? hls::kQuadChildren : 1); ++q)
        ++fifos_[std::size_t(pe.out_base + q)].producers;
    fifo_owner_.assign(fifos_.size(), -1);
    for (std::size_t p = 0; p < pes_.size(); ++p) fifo_owner_[std::size_t(pes_[p].in_fifo)] = int(p);
    pixel_active_.assign(std::size_t(pixel_units_), 0);
  }

  void reset() {
    for (auto& f : fifos_) {
      f.head = f.count = 0;
      f.popped = false;
      f.sleeper = -1;
    }
    woken_.clear();
    for (auto& p : pes_) {
      p.busy = false;
      p.todo = 0;
      p.active = false;
      p.asleep_since = -1;
      if (p.work) {
        p.work->lifo.clear();
        p.work->slot = -1;
        p.work->stalled_on = -1;
      }
    }
    active_pes_.clear();
    active_pixels_.clear();
    std::fill(pixel_active_.begin(), pixel_active_.end(), 0);
    pending_.clear();
    sets_.clear();
    free_.clear();
    for (int s = int(pool_.size()) - 1; s >= 0; --s) free_.push_back(s);
    in_flight_ = 0;
  }

  // Items live in a pool; FIFOs, LIFOs and PEs hold slot numbers (the model copies no windows).
  int allocate() {
    if (free_.empty()) {
      pool_.emplace_back();
      return int(pool_.size()) - 1;
    }
    const int s = free_.back();
    free_.pop_back();
    return s;
  }
  void release(int slot) { free_.push_back(slot); }

  void push(int fifo, int slot) {
    pending_.push_back({fifo, slot});
    ++in_flight_;
  }

  bool pop(int fifo, int& out) {
    Fifo& f = fifos_[std::size_t(fifo)];
    if (f.count == 0 || f.popped) return false;
    out = f.buf[std::size_t(f.head)];
    f.head = (f.head + 1) % cfg_.fifo_depth;
    --f.count;
    f.popped = true;
    if (f.sleeper >= 0) woken_.push_back(fifo);
    return true;
  }

  // One clock of PE `index`: a busy PE evaluates its next child (pe_evaluate), an idle one (or one
  // that has just finished its window) loads the next window (pe_load).
  void step_pe(int index, long long t, const hls::MaskMemory& masks, ArchStats& st, ArchTracer<P>* tracer) {
    if (pes_[std::size_t(index)].busy && !pe_evaluate(index, t, st, tracer)) return;
    pe_load(index, t, masks, st, tracer);
  }

  // A busy PE's clock: its next child tested and passed on (or the stall kept); true when the
  // window's last child is done and the PE may load in this clock.
  bool pe_evaluate(int index, long long t, ArchStats& st, ArchTracer<P>* tracer) {
    Pe& pe = pes_[std::size_t(index)];
    Work& w = *pe.work;
    if (w.stalled_on >= 0 && fifos_[std::size_t(w.stalled_on)].start_count() >= cfg_.fifo_depth) {
      ++st.pe_stall_cycles[std::size_t(index)];
      return false;  // still stalled: the same kept child, its output still full (model speed only)
    }
    const bool kept = w.stalled_on >= 0;  // w.child is this child's evaluation
    w.stalled_on = -1;
    const QuadItem<P>& held = pool_[std::size_t(w.slot)];
    int q = 0;
    while (((pe.todo >> q) & 1u) == 0) ++q;
    const int level = int(held.w.level.value()) + 1;
    const bool to_lifo = level < pe.last_level;
    const int dest = pe.out_base + (pe.out_by_quadrant ? q : 0);
    const bool room = to_lifo || fifos_[std::size_t(dest)].start_count() < cfg_.fifo_depth;
    if (!kept) hls::evaluate_child(held.w, q, n_, false, w.child, cfg_.side_log2);
    const hls::QuadChild<P>& child = w.child;
    if (child.covered) {
      if (!room) {
        ++st.pe_stall_cycles[std::size_t(index)];
        w.stalled_on = dest;
        Fifo& out = fifos_[std::size_t(dest)];
        if (out.producers == 1) {  // asleep until out is popped (Pe::asleep_since)
          pe.asleep_since = t;
          out.sleeper = index;
          if (out.popped) woken_.push_back(dest);  // popped earlier in this cycle
        }
        return false;  // stall: the same child again next cycle
      }
      const int slot = allocate();
      QuadItem<P>& it = pool_[std::size_t(slot)];
      const QuadItem<P>& parent = pool_[std::size_t(w.slot)];  // the pool may have grown
      it.w = child.window;
      it.samples = child.samples;
      it.piece = parent.piece;
      if (to_lifo) {
        w.lifo.push_back(slot);
        ++in_flight_;
      } else {
        push(dest, slot);
      }
      ++st.level[std::size_t(level)].covered;
      PieceStats& ps = st.pieces[it.piece];
      ps.deepest_level = std::max(ps.deepest_level, level);
      if (tracer) tracer->emit(t, index, q, it, child.full);
    }
    ++st.level[std::size_t(level)].tested;
    ++st.pe_busy_cycles[std::size_t(index)];
    const QuadItem<P>& parent = pool_[std::size_t(w.slot)];
    if (child.full && parent.w.poly.opaque) {
      ++st.level[std::size_t(level)].full_opaque;
      if (cfg_.masks) sets_.push_back({level - 1, int(parent.w.x.value()), int(parent.w.y.value()), q});
    }
    pe.todo &= ~(1u << q);
    if (pe.todo == 0) {
      pe.busy = false;
      release(w.slot);
      w.slot = -1;
      --in_flight_;
      return true;
    }
    return false;
  }

  // An idle PE's clock: the next window from its LIFO or its input FIFO, masked children dropped.
  void pe_load(int index, long long t, const hls::MaskMemory& masks, ArchStats& st, ArchTracer<P>* tracer) {
    Pe& pe = pes_[std::size_t(index)];
    int slot = -1;
    if (pe.work && !pe.work->lifo.empty()) {
      slot = pe.work->lifo.back();
      pe.work->lifo.pop_back();
    } else if (!pop(pe.in_fifo, slot)) {
      return;
    }
    const QuadItem<P>& next = pool_[std::size_t(slot)];
    // The popped item leaves a FIFO (or the LIFO) and becomes the PE's window (or is dropped).
    if (!pe.work) pe.work = std::make_unique<Work>();
    const int wl = int(next.w.level.value());
    const unsigned mask =
        cfg_.masks ? unsigned(hls::mask_read(masks, wl, int(next.w.x.value()), int(next.w.y.value())).value()) : 0u;
    LevelStats& ls = st.level[std::size_t(wl)];
    ++ls.loaded;
    st.level[std::size_t(wl) + 1].masked += __builtin_popcount(mask);
    if (mask != 0) st.pieces[next.piece].met_mask = true;
    if (tracer) tracer->load(t, index, next, mask);
    const unsigned path = start_window_children(next.w, cfg_.start_window);
    st.level[std::size_t(wl) + 1].outside_start += 4 - __builtin_popcount(path);
    pe.todo = ~mask & path;
    if (pe.todo == 0) {
      ++ls.loaded_all_masked;
      release(slot);
      --in_flight_;
      return;
    }
    pe.busy = true;
    pe.work->slot = slot;
  }

  void step_pixel(int unit, long long t, PixelSink<P>& sink, ArchStats& st, ArchTracer<P>* tracer) {
    if (stall_hit(cfg_.stall_seed, std::uint64_t(t), std::uint32_t(1 + unit), cfg_.output_stall_percent)) return;
    int slot = -1;
    if (!pop(pixel_fifo_base_ + unit, slot)) return;
    --in_flight_;
    const QuadItem<P>& it = pool_[std::size_t(slot)];
    bool full = false;
    const std::uint64_t fresh = sink.pixel(unit, it, full);
    ++st.pixel_records;
    PieceStats& ps = st.pieces[it.piece];
    ++ps.pixel_records;
    ps.last_cycle = t;
    if (tracer) tracer->pixel(t, unit, it, fresh, full);
    if (full) {
      ++st.pixels_full;
      const int x = int(it.w.x.value()), y = int(it.w.y.value());
      if (cfg_.masks) sets_.push_back({n_ - 1, x >> 1, y >> 1, ((y & 1) << 1) | (x & 1)});
    }
    release(slot);
  }

  void commit(long long t, hls::MaskMemory& masks, ArchStats& st, ArchTracer<P>* tracer) {
    // PEs asleep on a FIFO popped in this cycle: the cycles after the stall that put them to
    // sleep, up to this one, were stall cycles; from the next cycle they test their output again.
    for (int fifo : woken_) {
      Fifo& f = fifos_[std::size_t(fifo)];
      if (f.sleeper < 0) continue;
      Pe& pe = pes_[std::size_t(f.sleeper)];
      st.pe_stall_cycles[std::size_t(f.sleeper)] += t - pe.asleep_since;
      pe.asleep_since = -1;
      f.sleeper = -1;
    }
    woken_.clear();
    for (auto& [fifo, slot] : pending_) {
      Fifo& f = fifos_[std::size_t(fifo)];
      if (f.buf.empty()) f.buf.resize(std::size_t(cfg_.fifo_depth));
      f.buf[std::size_t((f.head + f.count) % cfg_.fifo_depth)] = slot;
      ++f.count;
    }
    for (auto& [fifo, slot] : pending_) {
      if (fifo >= pixel_fifo_base_) {
        const int u = fifo - pixel_fifo_base_;
        if (!pixel_active_[std::size_t(u)]) {
          pixel_active_[std::size_t(u)] = 1;
          active_pixels_.push_back(u);
        }
      } else {
        Pe& pe = pes_[std::size_t(fifo_owner_[std::size_t(fifo)])];
        if (!pe.active) {
          pe.active = true;
          active_pes_.push_back(fifo_owner_[std::size_t(fifo)]);
        }
      }
    }
    pending_.clear();
    for (const MaskSet& s : sets_) {
      if (tracer) tracer->mask_set(t, s.level, s.x, s.y, s.child);
      ++st.mask_sets;
      st.mask_words_full += hls::mask_set(masks, s.level, s.x, s.y, s.child);
    }
    sets_.clear();
    // Retire idle units from the active lists; clear the pop flags.
    std::size_t keep = 0;
    for (int p : active_pes_) {
      Pe& pe = pes_[std::size_t(p)];
      fifos_[std::size_t(pe.in_fifo)].popped = false;
      const bool live = pe.busy || fifos_[std::size_t(pe.in_fifo)].count > 0 || (pe.work && !pe.work->lifo.empty());
      if (live) active_pes_[keep++] = p;
      else pe.active = false;
    }
    active_pes_.resize(keep);
    keep = 0;
    for (int u : active_pixels_) {
      Fifo& f = fifos_[std::size_t(pixel_fifo_base_ + u)];
      f.popped = false;
      if (f.count > 0) active_pixels_[keep++] = u;
      else pixel_active_[std::size_t(u)] = 0;
    }
    active_pixels_.resize(keep);
  }

  struct MaskSet {
    int level, x, y, child;
  };

  Architecture arch_;
  ArchConfig cfg_;
  int n_;
  std::vector<Pe> pes_;
  std::vector<Fifo> fifos_;
  std::vector<int> fifo_owner_;
  int pixel_units_ = 1, pixel_fifo_base_ = 0;
  std::vector<int> active_pes_, active_pixels_;
  std::vector<char> pixel_active_;
  std::vector<std::pair<int, int>> pending_;  // (FIFO, item slot) pushed this cycle
  std::vector<QuadItem<P>> pool_;
  std::vector<int> free_;
  std::vector<MaskSet> sets_;
  std::vector<int> woken_;   // FIFOs popped in this cycle that a PE sleeps on
  long long in_flight_ = 0;  // items in FIFOs or LIFOs, pending pushes, and windows held by PEs
};

}  // namespace cig::quad
