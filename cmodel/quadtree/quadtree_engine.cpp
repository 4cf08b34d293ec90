#include "quadtree/quadtree_engine.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <type_traits>
#include <vector>

#include "common/error.hpp"
#include "common/timing.hpp"
#include "engine/rendering_parts.hpp"
#include "formatter/lattice_check.hpp"
#include "quadtree/pixel_merge.hpp"
#include "quadtree/quadtree_frame.hpp"

namespace cig {

namespace {

struct QuadOptions {
  std::string arch = "np";
  bool masks = true;
  bool start_window = false;  // start=bbox: each piece's subdivision starts at its start window
  std::string format = "fine";
  int fifo = 2;
  double clock_ns = kQuadDefaultClockNs;
  int side_log2 = hls::kDefaultSideLog2;  // spp = 4^t samples per pixel
  int threads = 1;                        // workers for one image (PixelFrame::set_threads)
};

constexpr double kFrameBudgetMs = 20.0;  // seed 004: t_0 = 20 ms (50 Hz)

template <class P>
class QuadProcessor {
 public:
  QuadProcessor(const QuadOptions& o, const char* name, const char* format)
      : options_(o), name_(name), format_(format), masks_(std::make_unique<hls::MaskMemory>()) {}

  // The raster's level count n and the architecture for it (InputError when they do not fit).
  quad::Architecture check_raster(int n_pix) const {
    const int log2 = hls::raster_log2_of(n_pix);
    if (log2 < hls::kMinRasterLog2 || log2 > hls::kMaxRasterLog2 || (1 << log2) != n_pix)
      throw InputError("", "raster",
                       "the quadtree engine renders rasters of 16 to 1024 lines, not " + std::to_string(n_pix));
    check_lattice(log2, options_.side_log2, "quadtree");
    return quad::Architecture::parse(options_.arch, log2);
  }

  // The architecture for the frame's raster, and its polygon count against the ids' 16 bits.
  quad::Architecture check_frame(const ScreenFrame& frame) const {
    const quad::Architecture arch = check_raster(frame.raster);
    check_counts(frame.frame, frame.channel, frame.polygons.size());
    return arch;
  }
  // A frame's polygons against the 16-bit ids (InputError).
  static void check_counts(int frame, int channel, std::size_t polygons) {
    if (polygons > std::size_t(hls::kMaxPolygonIds))
      throw InputError("", "polygons",
                       "the quadtree engine takes at most 65536 polygons per channel (the 16-bit polygon id "
                       "of its window records, which the pixel processor compares with the light points' "
                       "priority); frame " +
                           std::to_string(frame) + " channel " + std::to_string(channel) + " has " +
                           std::to_string(polygons) + " (the float engine takes up to " +
                           std::to_string(kMaxReferencePolygons) + ")");
  }

  EngineRun render(const ScreenFrame& frame) {
    const quad::Architecture arch = check_frame(frame);
    const int log2 = arch.raster_log2;
    const quad::ArchConfig cfg = arch_config();
    EngineRun run;
    auto& rep = run.report;
    rep["engine"] = name_;
    rep["format"] = format_;
    rep["architecture"] = arch.text;
    rep["masks"] = options_.masks;
    rep["start"] = options_.start_window ? "bbox" : "screen";
    rep["fifo_depth"] = options_.fifo;
    rep["samples_per_pixel"] = 1 << (2 * options_.side_log2);
    rep["threads"] = options_.threads;

    // Formatter and setup, in priority order (front to back).
    auto t0 = Clock::now();
    quad::FrontEndStats fe;
    const std::vector<hls::QuadWindow<P>> roots = quad::front_end<P>(frame, log2, fe, options_.side_log2);
    const double setup_ms = ms_since(t0);

    // Tables and the light point unit (lights rasterised before the polygons).
    t0 = Clock::now();
    pixels_.set_threads(options_.threads);
    pixels_.begin(frame, log2, options_.side_log2);
    const double lights_ms = ms_since(t0);

    // The architecture, clock by clock.
    t0 = Clock::now();
    hls::mask_clear(*masks_, log2);
    quad::ArchModel<P> model(arch, cfg);
    const quad::ArchStats st = model.run(roots, *masks_, pixels_);
    pixels_.finish();
    const double raster_ms = ms_since(t0);

    // Resolve.
    t0 = Clock::now();
    pixels_.resolve(run.out.image, run.out.ids);
    const double resolve_ms = ms_since(t0);

    report(frame, arch, model, fe, roots.size(), st, rep);
    rep["setup_ms"] = setup_ms;
    rep["lights_ms"] = lights_ms;
    rep["raster_ms"] = raster_ms;
    rep["resolve_ms"] = resolve_ms;
    return run;
  }

  // One rendering pipeline's part (seed 000's Nc): front end, light point unit and PEs into its own
  // pixel frame, which keeps its samples for the merge (quadtree/pixel_merge.hpp).
  nlohmann::ordered_json rasterise_part(const ScreenFrame& part) {
    const auto t0 = Clock::now();
    const quad::Architecture arch = check_frame(part);
    const quad::ArchConfig cfg = arch_config();
    quad::FrontEndStats fe;
    const std::vector<hls::QuadWindow<P>> roots = quad::front_end<P>(part, arch.raster_log2, fe, options_.side_log2);
    pixels_.keep_samples(true);
    pixels_.set_threads(1);  // each part is already on its own worker
    pixels_.begin(part, arch.raster_log2, options_.side_log2);
    hls::mask_clear(*masks_, arch.raster_log2);
    quad::ArchModel<P> model(arch, cfg);
    const quad::ArchStats st = model.run(roots, *masks_, pixels_);
    pixels_.finish();
    return {{"polygons", part.polygons.size()},
            {"light_points", part.light_points.size()},
            {"pieces", roots.size()},
            {"pixel_records", st.pixel_records},
            {"samples_written", pixels_.samples_written()},
            {"cycles", st.cycles},
            {"hardware_ms", double(st.cycles) * options_.clock_ns * 1e-6},
            {"ms", ms_since(t0)}};
  }
  const quad::PixelFrame<P>& pixels() const { return pixels_; }

 private:
  // The cycle model's settings from the engine's options.
  quad::ArchConfig arch_config() const {
    quad::ArchConfig cfg;
    cfg.fifo_depth = options_.fifo;
    cfg.masks = options_.masks;
    cfg.side_log2 = options_.side_log2;
    cfg.start_window = options_.start_window;
    return cfg;
  }

  // What the frame did: the front end, the PEs level by level, the masks, the cycles per stage.
  void report(const ScreenFrame& frame, const quad::Architecture& arch, const quad::ArchModel<P>& model,
              const quad::FrontEndStats& fe, std::size_t pieces, const quad::ArchStats& st,
              nlohmann::ordered_json& rep) const {
    rep["polygons"] = frame.polygons.size();
    rep["polygons_degenerate"] = fe.degenerate;
    rep["polygons_split"] = fe.split;
    rep["polygons_non_convex"] = fe.non_convex;  // snapped non-convex: drawn as span pieces
    rep["span_pieces"] = fe.span_pieces;
    rep["pieces"] = pieces;
    rep["bbox_edges"] = fe.bbox_edges;
    rep["light_points"] = frame.light_points.size();
    rep["light_samples"] = pixels_.light_samples();
    nlohmann::ordered_json levels = nlohmann::ordered_json::array();
    for (int l = 0; l <= arch.raster_log2; ++l) {
      const quad::LevelStats& ls = st.level[std::size_t(l)];
      levels.push_back({{"level", l},
                        {"windows_loaded", ls.loaded},
                        {"windows_all_masked", ls.loaded_all_masked},
                        {"children_tested", ls.tested},
                        {"children_masked", ls.masked},
                        {"children_outside_start", ls.outside_start},
                        {"children_covered", ls.covered},
                        {"children_full_opaque", ls.full_opaque}});
    }
    rep["levels"] = levels;
    // Pieces that met a mask and never reached the pixels: hidden, discarded at that level.
    std::vector<long> died(std::size_t(arch.raster_log2) + 1, 0);
    long hidden = 0;
    for (const quad::PieceStats& ps : st.pieces)
      if (ps.met_mask && ps.pixel_records == 0) {
        ++died[std::size_t(ps.deepest_level)];
        ++hidden;
      }
    rep["pieces_hidden_by_masks"] = hidden;
    rep["pieces_hidden_by_level"] = died;
    rep["pixel_records"] = st.pixel_records;
    rep["samples_written"] = pixels_.samples_written();
    rep["pixels_full"] = st.pixels_full;
    rep["mask_sets"] = st.mask_sets;
    rep["mask_words_full"] = st.mask_words_full;
    const double frame_ms = double(st.cycles) * options_.clock_ns * 1e-6;
    long long busy = 0;
    for (long long b : st.pe_busy_cycles) busy += b;
    nlohmann::ordered_json per_stage = nlohmann::ordered_json::array();
    for (std::size_t s = 0; s < arch.stages.size(); ++s) {
      long long sb = 0, ss = 0, pes = 0;
      for (int p = 0; p < model.pe_count(); ++p)
        if (model.pe_stage(p) == int(s)) {
          sb += st.pe_busy_cycles[std::size_t(p)];
          ss += st.pe_stall_cycles[std::size_t(p)];
          ++pes;
        }
      const quad::ArchStage& as = arch.stages[s];
      per_stage.push_back({{"kind", std::string(1, as.kind)},
                           {"levels", std::to_string(as.first_level) + ".." + std::to_string(as.last_level)},
                           {"pes", pes},
                           {"busy_cycles", sb},
                           {"stall_cycles", ss},
                           {"utilisation", st.cycles > 0 ? double(sb) / (double(st.cycles) * double(pes)) : 0.0}});
    }
    rep["hardware_ms"] = frame_ms;  // the modelled hardware time of the frame (cig sweep)
    rep["cycles"] = {{"frame", st.cycles},
                     {"per_piece", pieces == 0 ? 0.0 : double(st.cycles) / double(pieces)},
                     {"clock_ns", options_.clock_ns},
                     {"frame_ms", frame_ms},
                     {"budget_ms", kFrameBudgetMs},
                     {"fits_budget", frame_ms <= kFrameBudgetMs},
                     {"pes", model.pe_count()},
                     {"pe_utilisation", st.cycles > 0 ? double(busy) / (double(st.cycles) * model.pe_count()) : 0.0},
                     {"input_wait_cycles", st.input_wait_cycles},
                     {"stages", per_stage}};
  }

  QuadOptions options_;
  const char* name_;
  const char* format_;
  std::unique_ptr<hls::MaskMemory> masks_;
  quad::PixelFrame<P> pixels_;
};

template <class P>
class QuadEngine : public RasterEngine {
 public:
  QuadEngine(const QuadOptions& o, const char* name, const char* format)
      : name_(name), format_(format), options_(o), processor_(o, name, format) {}
  const char* name() const override { return name_; }
  void check_engine_raster(int raster) const override { processor_.check_raster(raster); }
  void check_counts(int frame, int channel, std::size_t polygons, std::size_t /*light_points*/) const override {
    QuadProcessor<P>::check_counts(frame, channel, polygons);
  }

 protected:
  EngineRun render_frame(const ScreenFrame& frame) override { return processor_.render(frame); }
  void check_split_frame(const ScreenFrame& frame) const override { processor_.check_frame(frame); }

  // Each part on its own pipeline and worker thread, then the merge of their samples.
  EngineRun render_split_parts(const std::vector<const ScreenFrame*>& parts) override {
    for (const ScreenFrame* part : parts) processor_.check_frame(*part);
    EngineRun run;
    run.report = {{"engine", name_},
                  {"format", format_},
                  {"architecture", options_.arch},
                  {"samples_per_pixel", 1 << (2 * options_.side_log2)}};
    rasterise_parts(
        parts_, parts, [&] { return std::make_unique<QuadProcessor<P>>(options_, name_, format_); }, run.report);
    std::vector<const quad::PixelFrame<P>*> frames;
    for (std::size_t k = 0; k < parts.size(); ++k) frames.push_back(&parts_[k]->pixels());
    const auto t0 = Clock::now();
    quad::PixelMerge<P>(frames, part_offsets(parts)).run(int(parts.size()), run.out);
    run.report["merge_ms"] = ms_since(t0);
    double slowest = 0;  // the pipelines work side by side: the slowest one's time is the frame's
    for (const auto& part : run.report["pipelines"]) slowest = std::max(slowest, part["hardware_ms"].get<double>());
    run.report["hardware_ms"] = slowest;
    return run;
  }
  bool renders_parts() const override { return true; }

 private:
  const char* name_;
  const char* format_;
  QuadOptions options_;
  QuadProcessor<P> processor_;
  std::vector<std::unique_ptr<QuadProcessor<P>>> parts_;  // --pipelines: one per part
};

}  // namespace

namespace {

// The syntax of an architecture (the level count is checked per frame, against the raster).
void check_architecture(const std::string& value) { quad::Architecture::parse(value, 0, "--arch"); }

}  // namespace

std::vector<EngineOptionSpec> quadtree_engine_options(bool twin) {
  std::vector<EngineOptionSpec> specs{
      syntax_option("arch", "eq. 1: np, 9p, 7p2t, 8s1p, ...", check_architecture, "np",
                    "the raster processor's architecture, any of seed 004's eq. 1 (np: one PE per level)", "--arch"),
      choice_option("masks", {"on", "off"}, "on", "multilevel priority masks", "--masks"),
      choice_option("start", {"screen", "bbox"}, "screen",
                    "where a polygon's subdivision starts: the whole screen (the seed's) or the smallest window "
                    "holding its bounding box (same image, fewer child tests)",
                    "--start-window")};
  if (!twin)
    specs.push_back(choice_option("format", {"coarse", "medium", "fine"}, "fine",
                                  "the parameter formats, hls/quadtree/records.hpp"));
  specs.push_back(integer_option("fifo", 1, 64, "2", "FIFO depth between stages"));
  specs.push_back(
      real_option("clock-ns", 0, 1e6, kQuadDefaultClockNs, "the clock period in ns the report converts cycles at"));
  specs.push_back(samples_per_pixel_option(hls::kMaxSideLog2));
  return specs;
}

std::unique_ptr<RasterEngine> make_quadtree_engine(const EngineOptions& options, bool twin) {
  const char* engine = quadtree_engine_declaration(twin).name;
  const EngineSettings s = parse_engine_options(engine, quadtree_engine_options(twin), options.params);
  QuadOptions o;
  o.threads = std::max(1, options.threads);
  o.arch = s.text("arch");
  o.masks = s.is("masks", "on");
  o.start_window = s.is("start", "bbox");
  if (!twin) o.format = s.text("format");
  o.fifo = s.integer("fifo");
  o.clock_ns = s.real("clock-ns");
  o.side_log2 = s.side_log2();
  if (twin) return std::make_unique<QuadEngine<QuadDoubleArith>>(o, engine, "double");
  if (o.format == "coarse")
    return std::make_unique<QuadEngine<hls::QuadFixedArith<hls::QuadFormatCoarse>>>(o, engine,
                                                                                    hls::QuadFormatCoarse::name);
  if (o.format == "medium")
    return std::make_unique<QuadEngine<hls::QuadFixedArith<hls::QuadFormatMedium>>>(o, engine,
                                                                                    hls::QuadFormatMedium::name);
  return std::make_unique<QuadEngine<hls::QuadFixedArith<hls::QuadFormatFine>>>(o, engine, hls::QuadFormatFine::name);
}

// Both engines' rows of `cig engines` (engine/engine_declaration.hpp).
const EngineDeclaration& quadtree_engine_declaration(bool twin) {
  EngineCapabilities fixed;
  fixed.bit_accurate = fixed.polygons = fixed.pipelines = fixed.formatter = true;
  fixed.hardware_model = "rtl/quadtree (qt_raster)";
  static const EngineDeclaration kFixed{
      "quadtree",
      "stages C and E: the formatter and seed 004's recursive-subdivision raster processor, clock by clock through "
      "its architecture",
      fixed,
      [](const EngineOptions& o) { return make_quadtree_engine(o, false); },
      [] { return quadtree_engine_options(false); },
      no_drop_kinds};
  static const EngineDeclaration kTwin{"quadtree-double",
                                       "stages C and E as `quadtree`, its kernels on double arithmetic (the twin)",
                                       twin_capabilities(fixed, kFixed.name),
                                       [](const EngineOptions& o) { return make_quadtree_engine(o, true); },
                                       [] { return quadtree_engine_options(true); },
                                       no_drop_kinds};
  return twin ? kTwin : kFixed;
}

}  // namespace cig
