#include "cosim.hpp"

#include <cmath>
#include <sstream>
#include <type_traits>

#include "common/error.hpp"
#include "common/timing.hpp"
#include "engine/fan_split.hpp"
#include "registry/engine_registry.hpp"

namespace cig::cosim {

std::string RtlConfig::arch_text() const {
  const int pipe = raster_log2 - tree_levels;
  if (tree_levels <= 1) return std::to_string(raster_log2) + "p";
  return (pipe > 0 ? std::to_string(pipe) + "p" : std::string()) + std::to_string(tree_levels) + "t";
}

Trace model_trace(const quad::Architecture& arch, const std::vector<hls::QuadWindow<RtlArith>>& roots,
                  quad::PixelFrame<RtlArith>& pixels, const StallConfig& stalls, int fifo_depth,
                  quad::ArchStats* stats) {
  const auto t0 = Clock::now();
  quad::ArchConfig cfg;
  cfg.fifo_depth = fifo_depth;
  cfg.masks = true;
  cfg.stall_seed = stalls.seed;
  cfg.input_gap_percent = stalls.input_gap_percent;
  cfg.output_stall_percent = stalls.output_stall_percent;
  cfg.start_window = stalls.start_window;
  quad::ArchModel<RtlArith> model(arch, cfg);
  const RtlLayout L = rtl_layout();
  Trace t;
  TraceRecorder<RtlArith> rec(L, t, model.pe_count(), model.pixel_units());
  auto masks = std::make_unique<hls::MaskMemory>();
  hls::mask_clear(*masks, arch.raster_log2);
  quad::ArchStats st = model.run(roots, *masks, pixels, &rec);
  t.cycles = st.cycles;
  std::sort(t.mask_sets.begin(), t.mask_sets.end());
  IdBuffer ids;
  pixels.resolve(t.image, ids);
  t.seconds = seconds_since(t0);
  if (stats) *stats = std::move(st);
  return t;
}

namespace {

const char* kind_name(EventKind k) { return k == EventKind::kLoad ? "load" : k == EventKind::kEmit ? "emit" : "pixel"; }

std::string event_text(const RtlLayout& L, const Event& e) {
  std::ostringstream s;
  s << kind_name(e.kind) << " at cycle " << e.cycle;
  if (e.kind == EventKind::kLoad) s << ", mask word " << e.mask;
  if (e.kind == EventKind::kEmit) s << ", child " << e.child << (e.full ? " (full)" : "");
  if (e.kind == EventKind::kPixel)
    s << ", samples taken 0x" << std::hex << e.mask << std::dec << (e.full ? " (pixel full)" : "");
  if (e.record.width() > 0) s << ": " << describe_record(L, e.record);
  return s.str();
}

struct FirstMismatch {
  long long cycle = -1;
  std::string text;
  void offer(long long c, const std::string& t) {
    if (cycle < 0 || c < cycle) {
      cycle = c;
      text = t;
    }
  }
};

void compare_stream(const RtlLayout& L, const std::string& name, const std::vector<Event>& m,
                    const std::vector<Event>& r, Comparison& out, FirstMismatch& first) {
  const std::size_t n = std::max(m.size(), r.size());
  for (std::size_t k = 0; k < n; ++k) {
    ++out.records_compared;
    if (k >= m.size() || k >= r.size()) {
      ++out.mismatches;
      const Event& e = k < m.size() ? m[k] : r[k];
      first.offer(e.cycle, name + " record " + std::to_string(k) + ": " +
                               (k < m.size() ? "missing in the RTL; the model has " : "extra in the RTL: ") +
                               event_text(L, e));
      continue;
    }
    const Event& a = m[k];
    const Event& b = r[k];
    std::string why;
    if (a.kind != b.kind) why = std::string("kind: expected ") + kind_name(a.kind) + ", got " + kind_name(b.kind);
    else if (a.cycle != b.cycle)
      why = "cycle: expected " + std::to_string(a.cycle) + ", got " + std::to_string(b.cycle);
    else if (a.child != b.child)
      why = "child: expected " + std::to_string(a.child) + ", got " + std::to_string(b.child);
    else if (a.mask != b.mask)
      why = std::string(a.kind == EventKind::kLoad ? "mask word" : "samples taken") + ": expected " +
            std::to_string(a.mask) + ", got " + std::to_string(b.mask);
    else if (a.full != b.full)
      why = std::string("full: expected ") + (a.full ? "1" : "0") + ", got " + (b.full ? "1" : "0");
    else if (a.record != b.record) why = first_field_difference(L, a.record, b.record);
    if (!why.empty()) {
      ++out.mismatches;
      first.offer(std::min(a.cycle, b.cycle),
                  name + " record " + std::to_string(k) + " (" + event_text(L, a) + "): " + why);
    }
  }
}

}  // namespace

Comparison compare_traces(const RtlLayout& L, const Trace& model, const Trace& rtl, bool compare_cycles) {
  Comparison out;
  FirstMismatch first;
  out.cycles_equal = !compare_cycles || model.cycles == rtl.cycles;
  if (!out.cycles_equal)
    first.offer(std::min(model.cycles, rtl.cycles),
                "frame cycles: expected " + std::to_string(model.cycles) + ", got " + std::to_string(rtl.cycles));
  if (model.pe.size() != rtl.pe.size() || model.pixel.size() != rtl.pixel.size()) {
    ++out.mismatches;
    first.offer(0, "architecture: the model has " + std::to_string(model.pe.size()) + " PEs and " +
                       std::to_string(model.pixel.size()) + " pixel processors, the RTL " +
                       std::to_string(rtl.pe.size()) + " and " + std::to_string(rtl.pixel.size()));
  } else {
    for (std::size_t p = 0; p < model.pe.size(); ++p)
      compare_stream(L, "PE " + std::to_string(p), model.pe[p], rtl.pe[p], out, first);
    for (std::size_t u = 0; u < model.pixel.size(); ++u)
      compare_stream(L, "pixel processor " + std::to_string(u), model.pixel[u], rtl.pixel[u], out, first);
  }
  // Mask sets: sorted multisets.
  std::size_t i = 0, j = 0;
  while (i < model.mask_sets.size() || j < rtl.mask_sets.size()) {
    ++out.records_compared;
    const bool take_m =
        j >= rtl.mask_sets.size() || (i < model.mask_sets.size() && model.mask_sets[i] < rtl.mask_sets[j]);
    const bool take_r =
        i >= model.mask_sets.size() || (j < rtl.mask_sets.size() && rtl.mask_sets[j] < model.mask_sets[i]);
    if (!take_m && !take_r) {
      ++i;
      ++j;
      continue;
    }
    ++out.mismatches;
    const MaskSetEvent& e = take_m ? model.mask_sets[i++] : rtl.mask_sets[j++];
    first.offer(e.cycle, std::string("mask set ") + (take_m ? "missing in the RTL" : "extra in the RTL") +
                             " at cycle " + std::to_string(e.cycle) + ": level " + std::to_string(e.level) + " word (" +
                             std::to_string(e.x) + ", " + std::to_string(e.y) + ") child " + std::to_string(e.child));
  }
  // Final pixels.
  if (model.image.width == rtl.image.width && model.image.height == rtl.image.height) {
    for (int y = 0; y < model.image.height; ++y)
      for (int x = 0; x < model.image.width; ++x) {
        ++out.records_compared;
        const std::uint8_t* a = model.image.at(x, y);
        const std::uint8_t* b = rtl.image.at(x, y);
        if (a[0] != b[0] || a[1] != b[1] || a[2] != b[2]) {
          ++out.mismatches;
          first.offer(model.cycles, "final pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                        "): expected RGB " + std::to_string(a[0]) + " " + std::to_string(a[1]) + " " +
                                        std::to_string(a[2]) + ", got " + std::to_string(b[0]) + " " +
                                        std::to_string(b[1]) + " " + std::to_string(b[2]));
        }
      }
  } else {
    ++out.mismatches;
    first.offer(model.cycles, "final image size differs");
  }
  out.first = first.text;
  return out;
}

CosimResult cosim_stream(const ScreenFrame& frame_for_tables, const std::vector<hls::QuadWindow<RtlArith>>& roots,
                         RtlRunner& rtl, const RtlConfig& cfg, const StallConfig& stalls, long long max_cycles,
                         const CycleProgress& progress, const BeforeRtl& before_rtl) {
  CosimResult r;
  const quad::Architecture arch = quad::Architecture::parse(cfg.arch_text(), cfg.raster_log2);
  quad::PixelFrame<RtlArith> pixels;
  pixels.begin(frame_for_tables, cfg.raster_log2);
  const std::size_t light_covers = std::size_t(rtl.params().light_covers);
  if (pixels.covers().size() > light_covers)
    throw InputError("", "light_points",
                     "the light points touch " + std::to_string(pixels.covers().size()) +
                         " pixels; the RTL's light-cover table (LIGHT_COVERS) holds " + std::to_string(light_covers));
  r.model = model_trace(arch, roots, pixels, stalls, 2, &r.stats);
  if (before_rtl) before_rtl(r.model.cycles);
  pixels.begin(frame_for_tables, cfg.raster_log2);  // the RTL starts from the same tables, cleared states
  if (progress) rtl.on_cycles([&](long long c) { progress(c, r.model.cycles); });
  try {
    r.rtl = rtl.run(roots, pixels, stalls, max_cycles);
  } catch (...) {
    rtl.on_cycles({});
    throw;
  }
  rtl.on_cycles({});
  r.comparison = compare_traces(rtl_layout(), r.model, r.rtl);
  return r;
}

namespace {

void check_raster(const ScreenFrame& frame, const RtlConfig& cfg) {
  if (frame.raster != (1 << cfg.raster_log2))
    throw InputError("", "--arch",
                     "the RTL configuration " + cfg.arch_text() + " renders " + std::to_string(1 << cfg.raster_log2) +
                         " lines; the input has " + std::to_string(frame.raster));
}

}  // namespace

CosimResult cosim_frame(const ScreenFrame& frame, RtlRunner& rtl, const RtlConfig& cfg, const StallConfig& stalls,
                        long long max_cycles, const CycleProgress& progress, const BeforeRtl& before_rtl) {
  check_raster(frame, cfg);
  quad::FrontEndStats fe;
  const std::vector<hls::QuadWindow<RtlArith>> roots = quad::front_end<RtlArith>(frame, cfg.raster_log2, fe);
  return cosim_stream(frame, roots, rtl, cfg, stalls, max_cycles, progress, before_rtl);
}

std::unique_ptr<RasterEngine> quadtree_engine(const RtlConfig& cfg, const StallConfig& stalls, bool fan_split) {
  EngineOptions o;
  o.fan_split = fan_split;
  o.params["arch"] = cfg.arch_text();
  o.params["start"] = stalls.start_window ? "bbox" : "screen";
  static_assert(std::is_same_v<RtlArith, hls::QuadFixedArith<hls::QuadFormatFine>>, "the engine's format=fine");
  o.params["format"] = "fine";
  return make_engine("quadtree", o);
}

EngineStream engine_stream(const RasterEngine& engine, const ScreenFrame& frame) {
  engine.check_frame(frame);
  FanSplit split;
  ScreenFrame snapped;
  EngineStream out;
  out.frame = engine.engine_frame(frame, split, snapped);
  out.fan_split = engine.fan_split();
  out.polygons_split = split.polygons_split;
  out.triangles_added = split.triangles_added;
  return out;
}

}  // namespace cig::cosim
