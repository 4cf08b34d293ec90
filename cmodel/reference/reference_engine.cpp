#include "reference/reference_engine.hpp"

#include "common/error.hpp"
#include "hls/formatter/sample_lattice.hpp"
#include "reference/reference_raster.hpp"
#include "reference/sample_lattice.hpp"

namespace cig {

namespace {

class FloatEngine : public RasterEngine {
 public:
  explicit FloatEngine(const EngineOptions& o) : options_(o) {
    const EngineSettings s = parse_engine_options(name(), reference_engine_options(), o.params);
    side_ = 1 << s.side_log2();
    visibility_ = s.is("visibility", "priority") ? Visibility::kPriority : Visibility::kDepth;
  }
  const char* name() const override { return reference_engine_declaration().name; }
  void check_counts(int frame, int channel, std::size_t polygons, std::size_t light_points) const override {
    if (polygons > kMaxReferencePolygons || light_points > kMaxReferencePolygons)
      throw InputError("", "polygons",
                       std::string("the ") + name() + " engine takes at most " + std::to_string(kMaxReferencePolygons) +
                           " polygons and as many light points per channel; frame " + std::to_string(frame) +
                           " channel " + std::to_string(channel) + " has " + std::to_string(polygons) + " and " +
                           std::to_string(light_points));
  }

 protected:
  // The grid the snapped reference rounds to: eq. 1's, or the one subpixel=B names (InputError
  // beyond kMaxGridBits).
  int snap_grid_bits(int raster) const {
    if (options_.subpixel_bits < 0) return kSeedGridBits;
    const int grid_bits = hls::raster_log2_of(raster) + options_.subpixel_bits;
    if (grid_bits > kMaxGridBits)
      throw InputError("", "--engine-opt",
                       std::string("engine '") + name() + "': subpixel=" + std::to_string(options_.subpixel_bits) +
                           " at " + std::to_string(raster) + " lines needs a " + std::to_string(grid_bits) +
                           "-bit grid; the reference snaps to at most " + std::to_string(kMaxGridBits) + " bits");
    return grid_bits;
  }
  void check_engine_raster(int raster) const override { snap_grid_bits(raster); }
  void check_split_frame(const ScreenFrame& frame) const override {
    snap_grid_bits(frame.raster);
    check_counts(frame.frame, frame.channel, frame.polygons.size(), frame.light_points.size());
  }
  EngineRun render_frame(const ScreenFrame& frame) override {
    check_split_frame(frame);
    ReferenceStats st;
    EngineRun run;
    const int grid_bits = snap_grid_bits(frame.raster);
    if (options_.snap) run.out = render_reference_snapped(frame, st, visibility_, side_, options_.threads, grid_bits);
    else run.out = render_reference(frame, st, visibility_, side_, options_.threads);
    run.report["engine"] = name();
    run.report["snapped"] = options_.snap;
    if (options_.snap) run.report["grid_bits"] = grid_bits;
    run.report["visibility"] = visibility_ == Visibility::kPriority ? "priority" : "depth";
    run.report["samples_per_pixel"] = side_ * side_;
    run.report["polygons"] = st.polygons;
    run.report["polygons_empty"] = st.polygons_empty;
    run.report["samples_covered"] = st.samples_covered;
    run.report["samples_written"] = st.samples_written;
    run.report["light_points"] = st.light_points;
    run.report["light_samples"] = st.light_samples;
    run.report["raster_ms"] = st.raster_ms;
    run.report["resolve_ms"] = st.resolve_ms;
    return run;
  }

 private:
  EngineOptions options_;
  Visibility visibility_ = Visibility::kDepth;
  int side_ = kSamplesPerSide;
};

}  // namespace

std::vector<EngineOptionSpec> reference_engine_options() {
  return {choice_option("visibility", {"depth", "priority"}, "depth",
                        "depth: a z-buffer; priority: each sample to the first polygon of the list that covers it, "
                        "as the raster engines"),
          samples_per_pixel_option(kMaxReferenceSideLog2)};
}

std::unique_ptr<RasterEngine> make_reference_engine(const EngineOptions& options) {
  return std::make_unique<FloatEngine>(options);
}

const EngineDeclaration& reference_engine_declaration() {
  EngineCapabilities can;
  can.polygons = can.reference = true;
  static const EngineDeclaration kFloat{
      "float",
      "the float reference (ground truth): a z-buffer on 1/Z, the seeds' Gouraud, fog and light points",
      can,
      make_reference_engine,
      reference_engine_options,
      no_drop_kinds};
  return kFloat;
}

}  // namespace cig
