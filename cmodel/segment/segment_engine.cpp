#include "segment/segment_engine.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <vector>

#include "common/error.hpp"
#include "common/parallel.hpp"
#include "common/timing.hpp"
#include "engine/rendering_parts.hpp"
#include "formatter/fog_table.hpp"
#include "formatter/formatter_twin.hpp"
#include "formatter/lattice_check.hpp"
#include "hls/formatter/formatter.hpp"
#include "hls/segment/edge_generator.hpp"
#include "hls/segment/frame_memory.hpp"
#include "hls/segment/light_segments.hpp"
#include "hls/segment/overload.hpp"
#include "hls/segment/segment_generator.hpp"
#include "hls/segment/span_piece_edges.hpp"
#include "hls/segment/video_channel.hpp"
#include "segment/double_arith.hpp"
#include "timing/segment_cycle_model.hpp"
#include "timing/segment_prediction.hpp"
#include "timing/timing_report.hpp"

namespace cig {

namespace {

// ---- The fixed/double twin adaptation -------------------------------------------------------------
// Front<P>: what differs between the bit-accurate processor (the formatter kernel, the coding table,
// the fog table) and its double twin (the formatter twin, exact chords, the fog formula). The
// quadtree engine adapts its twin the same way (QuadFront<P>, quadtree_frame.hpp).

template <class P>
struct Front;

template <class Fmt>
struct Front<hls::FixedSegmentArith<Fmt>> {
  using P = hls::FixedSegmentArith<Fmt>;
  static hls::FormattedPrimitive polygon(const ScreenPolygon& p, std::uint16_t id) {
    hls::FormattedPrimitive out;
    hls::formatter_top(raw_from_polygon(p, id), out);
    return out;
  }
  static hls::FormattedPrimitive light(const ScreenLightPoint& l, std::uint16_t id) {
    hls::FormattedPrimitive out;
    hls::formatter_top(raw_from_light(l, id), out);
    return out;
  }
  static int light_segments(const hls::FormattedPrimitive& l, int log2, int side_log2,
                            hls::Segment<P> (&out)[hls::kMaxLightSegments]) {
    return hls::generate_light_segments<P>(l, log2, hls::UInt<3>(0), out, side_log2);
  }
  static typename P::Level level(double unit) { return hls::UInt<8>(unit_to_byte(unit)); }
  static void fog_table(typename P::FogTable& t, const Fog& fog) { fill_fog_table(t, fog, false); }
  // Perspective-correct mode: the table indexed by the e8m7 code of 1/Z.
  static void fog_inverse_table(typename P::Plane::FogTable& t, const Fog& fog) { fill_fog_table(t, fog, true); }
  // A polygon that snapping made non-convex: its span pieces (hls/formatter/span_pieces.hpp).
  static bool split(const hls::FormattedPrimitive& f, int log2, int side_log2, hls::SpanPieces& pieces) {
    hls::split_into_span_pieces(f, log2, pieces, side_log2);
    return !pieces.convex;
  }
};

template <>
struct Front<DoubleSegmentArith> {
  using P = DoubleSegmentArith;
  static hls::FormattedPrimitiveT<P> convert(const TwinPrimitive& t) {
    hls::FormattedPrimitiveT<P> out;
    out.is_light = t.is_light;
    out.n = hls::UInt<5>(t.n);
    for (int k = 0; k < t.n; ++k) out.v[k] = {t.v[k].x, t.v[k].y, t.v[k].i, t.v[k].z};
    out.d = t.d;
    for (int c = 0; c < 3; ++c) out.colour[c] = t.colour[c];
    out.opaque = t.opaque;
    out.protect = t.protect;
    out.id = hls::UInt<16>(t.id);
    return out;
  }
  static hls::FormattedPrimitiveT<P> polygon(const ScreenPolygon& p, std::uint16_t id) {
    return convert(formatter_twin(p, id));
  }
  static hls::FormattedPrimitiveT<P> light(const ScreenLightPoint& l, std::uint16_t id) {
    return convert(formatter_twin(l, id));
  }
  // The twin of the coding table: the exact chord of the disc of diameter D at each row.
  static int light_segments(const hls::FormattedPrimitiveT<P>& l, int log2, int side_log2,
                            hls::Segment<P> (&out)[hls::kMaxLightSegments]) {
    const hls::LatticeGeometry g = hls::LatticeGeometry::for_raster(log2, side_log2);
    const int rows = g.rows(), within = g.side() - 1;
    const double cx = l.v[0].x, cy = l.v[0].y, d = l.d;  // half units: radius D/2 grid = D half
    int count = 0;
    for (int row = std::max(0, P::first_row_at_or_after(g, cy - 0.5 * d)); row < rows && count < hls::kMaxLightSegments;
         ++row) {
      const double dy = g.sample_half(row) - 2 * cy;
      if (std::abs(dy) > d) break;
      const double w = std::sqrt(d * d - dy * dy);
      hls::Segment<P>& s = out[count++];
      s.line = hls::UInt<10>(row >> side_log2);
      s.type = hls::UInt<3>(hls::kSegWhole);
      s.row_first = s.row_last = hls::UInt<3>(row & within);
      s.xl[row & within] = cx - 0.5 * w;
      s.xr[row & within] = cx + 0.5 * w + 1e-9;  // the disc's edge is inclusive
      s.il = s.ir = l.v[0].i;
      s.zl = s.zr = l.v[0].z;
      s.source = l.id;
      s.is_light = true;
      s.opaque = true;
    }
    return count;
  }
  static double level(double unit) { return std::clamp(unit, 0.0, 1.0) * 255; }
  // Both twin tables (by Z, by 1/Z) are the fog range itself.
  template <class Table>
  static void fog_table(Table& t, const Fog& fog) {
    t.start = fog.start;
    t.end = fog.end;
  }
  static void fog_inverse_table(P::Plane::FogTable& t, const Fog& fog) { fog_table(t, fog); }
  // The twin keeps the formatter's unsnapped positions: a convex polygon stays convex.
  static bool split(const hls::FormattedPrimitiveT<P>&, int, int, hls::SpanPieces&) { return false; }
};

// ---- The processor ---------------------------------------------------------------------------------

template <class P>
class SegmentProcessor {
 public:
  SegmentProcessor()
      : frame_memory_(std::make_unique<hls::FrameMemory<P>>()),
        segment_memory_(std::make_unique<hls::SegmentMemory<P>>()),
        tables_(std::make_unique<hls::VideoTables<P>>()),
        line_(std::make_unique<hls::LineBuffer<P>>()),
        segments_(std::make_unique<hls::Segment<P>[]>(hls::kMaxLines)),
        span_pieces_(std::make_unique<hls::SpanPieces>()) {}

  // seed_quadrilateral: the seed's four-X segment (x-rows=2); seed_interpolation: the seed's I and
  // Z at segment ends (eq. 3-4), interpolated along the row (interp=seed), instead of the planes.
  // side_log2: S = 2^t sample rows per line and samples per row of a pixel.
  // budget_ms > 0: the governor's time budget for the field passes (timing/segment_prediction.hpp).
  SegmentProcessor(bool seed_quadrilateral, bool seed_interpolation, int side_log2, double budget_ms = 0)
      : SegmentProcessor() {
    seed_quadrilateral_ = seed_quadrilateral;
    seed_interpolation_ = seed_interpolation;
    side_log2_ = side_log2;
    budget_ms_ = budget_ms;
  }

  // The raster's log2 and the frame's counts against the hardware's (InputError).
  static int check_frame(const ScreenFrame& frame, int side_log2) {
    const int n = frame.raster;
    const int log2 = hls::raster_log2_of(n);
    if (log2 < hls::kMinRasterLog2 || log2 > hls::kMaxRasterLog2)
      throw InputError("", "raster",
                       "the segment engine renders rasters of 16 to 1024 lines, not " + std::to_string(n));
    check_lattice(log2, side_log2, "segment");
    check_counts(frame.frame, frame.channel, frame.polygons.size(), frame.light_points.size());
    return log2;
  }
  // A frame's polygons and light points against the 16-bit ids (InputError).
  static void check_counts(int frame, int channel, std::size_t polygons, std::size_t light_points) {
    if (polygons > std::size_t(hls::kMaxPolygonIds) || light_points > std::size_t(hls::kMaxPolygonIds))
      throw InputError("", "polygons",
                       "the segment engine takes at most 65536 polygons and 65536 light points per channel (the "
                       "16-bit polygon id of its frame-memory and segment records, and the video channel's colour "
                       "and plane tables of 65536 entries); frame " +
                           std::to_string(frame) + " channel " + std::to_string(channel) + " has " +
                           std::to_string(polygons) + " and " + std::to_string(light_points) +
                           " (the float engine takes up to " + std::to_string(kMaxReferencePolygons) + ")");
  }

  EngineRun render(const ScreenFrame& frame, const char* engine_name, const char* format_name) {
    const int log2 = check_frame(frame, side_log2_);
    FrameStats st;
    auto t0 = Clock::now();
    format_and_count(frame, log2, st);
    st.front_ms = ms_since(t0);
    t0 = Clock::now();
    generate_and_sort(frame, log2, st);
    st.middle_ms = ms_since(t0);
    t0 = Clock::now();
    EngineRun run;
    video(frame, log2, run.out, st);
    st.video_ms = ms_since(t0);
    run.report = report(frame, engine_name, format_name, st);
    return run;
  }

  // What the frame lost to full memories (SPEC D, the seed's overload behaviour; the CLI warns,
  // cli_common.hpp drop_warning): polygons the overload threshold dropped, polygons the frame
  // memory had no room for, segments the segment memory had no room for.
  nlohmann::ordered_json dropped(long dropped_overload) const {
    return {
        {"polygons_overload", dropped_overload},
        {"polygons_frame_memory_full", frame_memory_->polygons_overflowed.value()},
        {"segments_segment_memory_full", segment_memory_->dropped[0].value() + segment_memory_->dropped[1].value()}};
  }

  // Workers for the video channel's lines (EngineOptions::threads): the same bits.
  void set_threads(int threads) { threads_ = std::max(1, threads); }

  // The last frame's records as the cycle model takes them.
  const SegmentLoad& load() const { return load_; }

  // One rendering pipeline's part (seed 000's Nc): formatter, edge and segment generators into its
  // own frame and segment memories, and its video tables; the video stage (merge_parts) reads it.
  nlohmann::ordered_json rasterise_part(const ScreenFrame& part) {
    const auto t0 = Clock::now();
    const int log2 = check_frame(part, side_log2_);
    FrameStats st;
    format_and_count(part, log2, st);
    generate_and_sort(part, log2, st);
    load_video_tables(part);
    return {{"polygons", part.polygons.size()},
            {"light_points", part.light_points.size()},
            {"segments", st.polygon_segments + st.light_segments},
            {"dropped", dropped(st.dropped_overload)},
            {"ms", ms_since(t0)}};
  }

  // The video stage of N pipelines, line by line (lines shared among `threads` workers): each
  // line's segments drawn from every part's segment memory in part order, so that a sample keeps
  // the first part's colour (the same visibility by priority as one list); the samples' polygons
  // renumbered into the whole list (offsets[k]: the polygons before part k). Returns the segments read.
  static long merge_parts(const std::vector<SegmentProcessor*>& parts, const std::vector<std::int32_t>& offsets, int n,
                          int threads, RasterImage& out) {
    const int side_log2 = parts[0]->side_log2_;
    const hls::LatticeGeometry g = hls::LatticeGeometry::for_raster(hls::raster_log2_of(n), side_log2);
    const int cols = g.rows(), side = g.side();
    out.image = Image(n, n);
    out.ids = IdBuffer(n, n);
    struct Worker {
      std::unique_ptr<hls::LineBuffer<P>> line = std::make_unique<hls::LineBuffer<P>>();
      std::unique_ptr<hls::PixelLine> pixels = std::make_unique<hls::PixelLine>();
      std::vector<char> renumbered;
      long read = 0;
    };
    std::vector<Worker> workers(std::size_t(std::max(1, threads)));
    parallel_for(std::size_t(n), threads, [&](std::size_t line, int self) {
      Worker& w = workers[std::size_t(self)];
      hls::clear_line_buffer(g, cols, *w.line);
      w.renumbered.assign(std::size_t(side * cols), 0);
      for (std::size_t k = 0; k < parts.size(); ++k) {
        w.read += hls::draw_line(int(line), g, cols, *parts[k]->segment_memory_, *parts[k]->tables_, *w.line);
        for (int r = 0; r < side; ++r)
          for (int i = 0; i < cols; ++i) {
            int& polygon = w.line->polygon[r][i];
            char& done = w.renumbered[std::size_t(r * cols + i)];
            if (polygon >= 0 && !done) polygon += offsets[k];
            done = polygon >= 0;
          }
      }
      for (int px = 0; px < n; ++px) hls::resolve_pixel(px, g, *parts[0]->tables_, *w.line, *w.pixels);
      store_line(int(line), n, *w.pixels, out);
    });
    long read = 0;
    for (const Worker& w : workers) read += w.read;
    return read;
  }

 private:
  using F = Front<P>;

  // What one frame did, for the report.
  struct FrameStats {
    int bank = 0, threshold = 0;
    hls::OverloadCounts counts;
    long degenerate = 0, edges_stored = 0, protected_polygons = 0;
    long non_convex = 0, span_pieces = 0;  // polygons snapping made non-convex, and their pieces
    long light_segments_field[2] = {0, 0};
    long light_segments = 0, polygon_segments = 0, dropped_overload = 0;
    long dropped_by_code[hls::kAreaCodes] = {};
    long read = 0, max_per_line = 0;
    double front_ms = 0, middle_ms = 0, video_ms = 0;
    // The governor's input: the frame memory's records (their ids) and the light points' segments.
    std::vector<PlannedRecord> planned_polygons, planned_lights;
    std::vector<long> planned_ids;
    int memory_threshold = 0;  // the overload threshold the segment memory alone sets
    double predicted_ns = 0, predicted_ungoverned_ns = 0;
    double predicted_next_ns = 0;  // at the threshold above the governor's (it did not fit), or 0
  };

  // A light point formatted and cut into segments by the coding table (into light_out_).
  int light_segments_of(const ScreenFrame& frame, std::size_t li, int log2) {
    const auto fl = F::light(frame.light_points[li], std::uint16_t(li));
    for (int c = 0; c < 3; ++c) tables_->light_colour[li][c] = fl.colour[c];
    return F::light_segments(fl, log2, side_log2_, light_out_);
  }

  // A polygon (or a span piece of one) into the frame memory, its segments counted.
  void store(const hls::PolygonEdges<P>& edges, FrameStats& st) {
    if (!hls::frame_memory_write(edges, *frame_memory_)) return;
    hls::overload_count(edges.h, st.counts);
    const auto edge_words = edges.h.left_count.value() + edges.h.right_count.value();
    st.edges_stored += long(edge_words);
    if (budget_ms_ > 0) {
      st.planned_polygons.push_back(
          {std::uint32_t(edge_words),
           {std::uint32_t(edges.h.segments_even.value()), std::uint32_t(edges.h.segments_odd.value())},
           int(edges.h.area_code.value()),
           false});
      st.planned_ids.push_back(long(edges.h.id.value()));
    }
    st.protected_polygons += edges.h.protect ? 1 : 0;
  }

  // Formatter and edge generator: polygons into the frame memory, segments counted per area code,
  // and the overload threshold.
  void format_and_count(const ScreenFrame& frame, int log2, FrameStats& st) {
    hls::frame_memory_swap(*frame_memory_);
    st.bank = frame_memory_->write_bank;
    hls::overload_reset(st.counts);
    hls::PolygonEdges<P> edges;
    for (std::size_t pi = 0; pi < frame.polygons.size(); ++pi) {
      const auto fp = F::polygon(frame.polygons[pi], std::uint16_t(pi));
      for (int c = 0; c < 3; ++c) tables_->polygon_colour[pi][c] = fp.colour[c];
      if (F::split(fp, log2, side_log2_, *span_pieces_)) {
        ++st.non_convex;
        st.span_pieces += long(span_pieces_->count.value());
        if (span_pieces_->count.value() == 0) ++st.degenerate;  // no sample row crosses it
        for (int k = 0; k < int(span_pieces_->count.value()); ++k) {
          hls::generate_span_piece_edges<P>(fp, span_pieces_->piece[k], log2, edges, side_log2_);
          store(edges, st);
        }
        continue;
      }
      hls::generate_edges<P>(fp, log2, edges, side_log2_);
      if (!edges.valid) {
        ++st.degenerate;
        continue;
      }
      store(edges, st);
    }
    // Light points are never dropped: their segments (coding table) count with the protected
    // polygons' in code 0, so that the threshold leaves room for them in both banks (SPEC D: the
    // threshold makes the frame's segments fit).
    for (std::size_t li = 0; li < frame.light_points.size(); ++li) {
      const int k = light_segments_of(frame, li, log2);
      std::uint32_t per_field[2] = {0, 0};
      for (int s = 0; s < k; ++s) ++per_field[light_out_[s].line.value() & 1];
      if (budget_ms_ > 0) st.planned_lights.push_back({0, {per_field[0], per_field[1]}, 0, true});
      for (int f = 0; f < 2; ++f) st.light_segments_field[f] += long(per_field[f]);
    }
    for (int f = 0; f < 2; ++f)
      st.counts.segments[f][0] = hls::UInt<24>(st.counts.segments[f][0].value() + st.light_segments_field[f]);
    st.threshold = st.memory_threshold = hls::overload_threshold_top(st.counts, hls::kSegmentBankWords);
    if (budget_ms_ > 0) govern(frame, st);
  }

  // The governor: the largest threshold whose field passes, the cycle model run on the records in
  // the order the preprocessor will read them, fit the budget (timing/segment_prediction.hpp).
  void govern(const ScreenFrame& frame, FrameStats& st) const {
    std::vector<PlannedRecord> plan;
    plan.reserve(st.planned_polygons.size() + st.planned_lights.size());
    const std::vector<std::size_t> lights = lights_by_priority(frame);
    std::size_t next = 0;
    auto lights_before = [&](long id) {
      for (; next < lights.size() && frame.light_points[lights[next]].priority <= id; ++next)
        plan.push_back(st.planned_lights[lights[next]]);
    };
    for (std::size_t k = 0; k < st.planned_polygons.size(); ++k) {
      lights_before(st.planned_ids[k]);
      plan.push_back(st.planned_polygons[k]);
    }
    lights_before(long(frame.polygons.size()));
    const SegmentTimingParams p;
    st.predicted_ungoverned_ns = planned_back_ns(plan, frame.raster, st.memory_threshold, p);
    st.threshold = governed_threshold(plan, frame.raster, budget_ms_ * 1e6, st.memory_threshold, p);
    st.predicted_ns = planned_back_ns(plan, frame.raster, st.threshold, p);
    if (st.threshold < st.memory_threshold)
      st.predicted_next_ns = planned_back_ns(plan, frame.raster, st.threshold + 1, p);
  }

  // The light points in the order the Y sorter takes them (stable by priority): each before the
  // first polygon whose id is not below its priority.
  static std::vector<std::size_t> lights_by_priority(const ScreenFrame& frame) {
    std::vector<std::size_t> order(frame.light_points.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return frame.light_points[a].priority < frame.light_points[b].priority;
    });
    return order;
  }

  // Preprocessor + segment generator + light coding table, into the Y sorter in priority order.
  void generate_and_sort(const ScreenFrame& frame, int log2, FrameStats& st) {
    hls::y_sorter_reset(*segment_memory_, frame.raster);
    start_load(frame.raster, st);
    const std::vector<std::size_t> light_order = lights_by_priority(frame);
    std::size_t next_light = 0;
    auto emit_lights_before = [&](long priority) {
      for (; next_light < light_order.size() && frame.light_points[light_order[next_light]].priority <= priority;
           ++next_light) {
        const int k = light_segments_of(frame, light_order[next_light], log2);
        load_.items.push_back({0, {0, 0}, true, false});
        for (int s = 0; s < k; ++s) sort_segment(light_out_[s]);
        st.light_segments += k;
      }
    };
    hls::PolygonEdges<P> edges;
    int addr = 0;
    while (hls::frame_memory_read(*frame_memory_, st.bank, addr, edges)) {
      emit_lights_before(long(edges.h.id.value()));
      tables_->polygon_planes[edges.h.id.value()] = edges.h.planes;
      const int code = int(edges.h.area_code.value());
      load_.items.push_back({std::uint32_t(edges.h.left_count.value() + edges.h.right_count.value()),
                             {0, 0},
                             false,
                             code > st.threshold});
      if (code > st.threshold) {
        ++st.dropped_overload;
        ++st.dropped_by_code[code];
        continue;
      }
      hls::Segment<P>(&out)[hls::kMaxLines] = *reinterpret_cast<hls::Segment<P>(*)[hls::kMaxLines]>(segments_.get());
      const int k = hls::generate_segments<P>(edges, log2, hls::UInt<3>(std::uint64_t(frame.channel & 7)),
                                              seed_quadrilateral_, out, side_log2_);
      for (int s = 0; s < k; ++s) sort_segment(out[s]);
      st.polygon_segments += k;
    }
    emit_lights_before(long(frame.polygons.size()));
    for (int line = 0; line < frame.raster; ++line)
      load_.line_segments[std::size_t(line)] = std::uint32_t(segment_memory_->count[line].value());
  }

  // Stage D in time (timing/segment_cycle_model.hpp): the frame memory's records as the
  // preprocessor reads them, each one's stored segments per field, and each line's last writer.
  void start_load(int raster, const FrameStats& st) {
    load_.raster_lines = raster;
    load_.edges_formed = std::uint64_t(st.edges_stored);
    load_.items.clear();
    load_.line_segments.assign(std::size_t(raster), 0);
    load_.line_last_item.assign(std::size_t(raster), -1);
  }
  void sort_segment(const hls::Segment<P>& seg) {
    if (!hls::y_sort(seg, *segment_memory_)) return;  // the bank was full: nothing written
    const int line = int(seg.line.value());
    ++load_.items.back().segments[line & 1];
    load_.line_last_item[std::size_t(line)] = std::int32_t(load_.items.size() - 1);
  }

  // The video channel's tables for a frame (fog, fog colour, background, interpolation mode).
  void load_video_tables(const ScreenFrame& frame) {
    F::fog_table(tables_->fog, frame.fog);
    F::fog_inverse_table(tables_->fog_inverse, frame.fog);
    tables_->plane_mode = !seed_interpolation_;
    for (int c = 0; c < 3; ++c) {
      tables_->fog_colour[c] = F::level(frame.fog.colour[c]);
      tables_->background[c] = F::level(frame.background[c]);
    }
  }

  // Video channel, line by line.
  void video(const ScreenFrame& frame, int log2, RasterImage& out, FrameStats& st) {
    const int n = frame.raster;
    load_video_tables(frame);
    if (threads_ > 1) {  // lines shared among the workers, each with its own line buffer
      st.read = merge_parts({this}, {0}, n, threads_, out);
      for (int line = 0; line < n; ++line)
        st.max_per_line = std::max<long>(st.max_per_line, long(segment_memory_->count[line].value()));
      return;
    }
    out.image = Image(n, n);
    out.ids = IdBuffer(n, n);
    hls::PixelLine pixels;
    for (int line = 0; line < n; ++line) {
      st.read += hls::render_line(line, log2, *segment_memory_, *tables_, *line_, pixels, side_log2_);
      st.max_per_line = std::max<long>(st.max_per_line, long(segment_memory_->count[line].value()));
      store_line(line, n, pixels, out);
    }
  }

  static void store_line(int line, int n, const hls::PixelLine& pixels, RasterImage& out) {
    for (int px = 0; px < n; ++px) {
      std::uint8_t* dst = out.image.at(px, line);
      for (int c = 0; c < 3; ++c) dst[c] = std::uint8_t(pixels.rgb[px][c].value());
      out.ids.id[std::size_t(line) * std::size_t(n) + std::size_t(px)] = pixels.id[px];
    }
  }

  nlohmann::ordered_json report(const ScreenFrame& frame, const char* engine_name, const char* format_name,
                                const FrameStats& st) const {
    nlohmann::ordered_json rep;
    rep["engine"] = engine_name;
    rep["format"] = format_name;
    rep["seed_quadrilateral"] = seed_quadrilateral_;
    rep["interpolation"] = seed_interpolation_ ? "seed" : "plane";
    rep["samples_per_pixel"] = 1 << (2 * side_log2_);
    const int n = frame.raster;
    const long stored = segment_memory_->used[0] + segment_memory_->used[1];
    const long lost = long(segment_memory_->dropped[0].value() + segment_memory_->dropped[1].value());
    rep["polygons"] = frame.polygons.size();
    rep["polygons_degenerate"] = st.degenerate;
    rep["polygons_non_convex"] = st.non_convex;  // snapped non-convex: stored as span pieces,
    rep["span_pieces"] = st.span_pieces;         // one frame-memory entry each
    rep["polygons_protected"] = st.protected_polygons;
    rep["edges"] = st.edges_stored;
    rep["frame_memory"] = {{"bank_words", hls::kFrameBankWords},
                           {"words_used", frame_memory_->used[st.bank]},
                           {"polygons_written", frame_memory_->polygons_written.value()},
                           {"polygons_overflowed", frame_memory_->polygons_overflowed.value()}};
    nlohmann::ordered_json per_code = nlohmann::ordered_json::array();
    for (int c = 0; c < hls::kAreaCodes; ++c)
      per_code.push_back({{"code", c},
                          {"segments_even", st.counts.segments[0][c].value()},
                          {"segments_odd", st.counts.segments[1][c].value()},
                          {"polygons_dropped", st.dropped_by_code[c]}});
    // per_area_code[0] counts the protected polygons' segments and the light points'.
    rep["overload"] = {
        {"bank_capacity", hls::kSegmentBankWords},           {"threshold", st.threshold},
        {"light_segments_even", st.light_segments_field[0]}, {"light_segments_odd", st.light_segments_field[1]},
        {"polygons_dropped", st.dropped_overload},           {"per_area_code", per_code}};
    rep["segments"] = {{"polygon", st.polygon_segments},
                       {"light", st.light_segments},
                       {"stored_even", segment_memory_->used[0]},
                       {"stored_odd", segment_memory_->used[1]},
                       {"dropped_memory_full", lost},
                       {"per_line_max", st.max_per_line},
                       {"per_line_mean", n ? double(stored) / n : 0.0},
                       {"read_by_video", st.read}};
    rep["light_points"] = frame.light_points.size();
    rep["dropped"] = dropped(st.dropped_overload);
    // Stage D in time (timing/segment_cycle_model.hpp). Its two frame-level stages, the edge
    // generator (beside stage B) and the field passes, each take a frame; the slower bounds the rate.
    const SegmentFrameTiming t = time_segment_frame({load_});
    rep["hardware_ms"] = std::max(t.front_ns, t.back_ns) * 1e-6;  // the modelled hardware time (cig sweep)
    rep["cycle_model"] = segment_timing_json(t);
    if (budget_ms_ > 0) rep["governor"] = governor_report(st, t);
    rep["front_ms"] = st.front_ms;
    rep["segments_ms"] = st.middle_ms;
    rep["video_ms"] = st.video_ms;
    return rep;
  }

  // What the governor predicted and did, against the cycle model's time of the same frame.
  nlohmann::ordered_json governor_report(const FrameStats& st, const SegmentFrameTiming& t) const {
    long dropped = 0;
    for (int c = st.threshold + 1; c <= st.memory_threshold; ++c) dropped += st.dropped_by_code[c];
    return {{"budget_ms", budget_ms_},
            {"memory_threshold", st.memory_threshold},
            {"threshold", st.threshold},
            {"polygons_dropped", dropped},
            {"predicted_ungoverned_ms", st.predicted_ungoverned_ns * 1e-6},
            {"predicted_ms", st.predicted_ns * 1e-6},
            {"predicted_at_next_threshold_ms", st.predicted_next_ns * 1e-6},
            {"modelled_ms", t.back_ns * 1e-6},
            {"prediction_error", t.back_ns > 0 ? st.predicted_ns / t.back_ns - 1 : 0.0},
            {"over_budget", t.back_ns > budget_ms_ * 1e6}};
  }

  hls::Segment<P> light_out_[hls::kMaxLightSegments];
  SegmentLoad load_;  // the last frame's, for the cycle model
  std::unique_ptr<hls::FrameMemory<P>> frame_memory_;
  std::unique_ptr<hls::SegmentMemory<P>> segment_memory_;
  std::unique_ptr<hls::VideoTables<P>> tables_;
  std::unique_ptr<hls::LineBuffer<P>> line_;
  std::unique_ptr<hls::Segment<P>[]> segments_;
  std::unique_ptr<hls::SpanPieces> span_pieces_;  // of the polygon being formatted
  bool seed_quadrilateral_ = false;
  bool seed_interpolation_ = false;
  int side_log2_ = hls::kDefaultSideLog2;
  int threads_ = 1;
  double budget_ms_ = 0;
};

template <class P>
class SegmentEngine : public RasterEngine {
 public:
  SegmentEngine(const char* name, const char* format, bool quad, bool seed_interp, int side_log2, int threads,
                double budget_ms)
      : name_(name),
        format_(format),
        side_log2_(side_log2),
        quad_(quad),
        interp_(seed_interp),
        budget_ms_(budget_ms),
        processor_(quad, seed_interp, side_log2, budget_ms) {
    processor_.set_threads(threads);
  }
  const char* name() const override { return name_; }
  const std::vector<DropKind>& drop_kinds() const override { return segment_drop_kinds(); }
  void check_engine_raster(int raster) const override {
    ScreenFrame f;
    f.raster = raster;
    SegmentProcessor<P>::check_frame(f, side_log2_);
  }
  void check_counts(int frame, int channel, std::size_t polygons, std::size_t light_points) const override {
    SegmentProcessor<P>::check_counts(frame, channel, polygons, light_points);
  }

 protected:
  EngineRun render_frame(const ScreenFrame& frame) override { return processor_.render(frame, name_, format_); }

  // Each part on its own pipeline and worker thread, then the merged video stage.
  EngineRun render_split_parts(const std::vector<const ScreenFrame*>& parts) override {
    for (const ScreenFrame* part : parts) SegmentProcessor<P>::check_frame(*part, side_log2_);
    EngineRun run;
    run.report = {{"engine", name_}, {"format", format_}, {"samples_per_pixel", 1 << (2 * side_log2_)}};
    rasterise_parts(
        parts_, parts, [&] { return std::make_unique<SegmentProcessor<P>>(quad_, interp_, side_log2_, budget_ms_); },
        run.report);
    std::vector<SegmentProcessor<P>*> pipes;
    for (std::size_t k = 0; k < parts.size(); ++k) pipes.push_back(parts_[k].get());
    const auto t0 = Clock::now();
    run.report["segments_read_by_video"] =
        SegmentProcessor<P>::merge_parts(pipes, part_offsets(parts), parts[0]->raster, int(parts.size()), run.out);
    run.report["video_ms"] = ms_since(t0);
    nlohmann::ordered_json total = nlohmann::ordered_json::object();
    for (const auto& part : run.report["pipelines"])
      for (const auto& item : part["dropped"].items())
        total[item.key()] = total.value(item.key(), 0L) + item.value().template get<long>();
    run.report["dropped"] = total;
    std::vector<SegmentLoad> loads;
    for (std::size_t k = 0; k < parts.size(); ++k) loads.push_back(parts_[k]->load());
    const SegmentFrameTiming t = time_segment_frame(loads);
    run.report["hardware_ms"] = std::max(t.front_ns, t.back_ns) * 1e-6;
    run.report["cycle_model"] = segment_timing_json(t);
    return run;
  }
  bool renders_parts() const override { return true; }
  void check_split_frame(const ScreenFrame& frame) const override {
    SegmentProcessor<P>::check_frame(frame, side_log2_);
  }

 private:
  const char* name_;
  const char* format_;
  int side_log2_;
  bool quad_, interp_;
  double budget_ms_;
  SegmentProcessor<P> processor_;
  std::vector<std::unique_ptr<SegmentProcessor<P>>> parts_;  // --pipelines: one per part
};

}  // namespace

namespace {

// budget-ms=off | MS: a time budget in ms, > 0 and finite.
void check_budget(const std::string& value) {
  if (value == "off") return;
  std::size_t used = 0;
  double ms = 0;
  try {
    ms = std::stod(value, &used);
  } catch (const std::exception&) { used = 0; }
  if (used != value.size() || !(ms > 0) || !(ms <= 1e6))
    throw InputError("", "budget-ms", "'" + value + "' is not off or a number of ms in (0, 1e6]");
}

double budget_of(const EngineSettings& s) { return s.is("budget-ms", "off") ? 0.0 : std::stod(s.text("budget-ms")); }

}  // namespace

std::vector<EngineOptionSpec> segment_engine_options(bool twin) {
  std::vector<EngineOptionSpec> specs;
  if (!twin)
    specs.push_back(choice_option("format", {"coarse", "medium", "fine"}, "fine",
                                  "the kernels' word formats, hls/segment/segment_arith.hpp"));
  specs.push_back(choice_option("x-rows", {"4", "2"}, "4",
                                "X at every sample row (4) or the seed's four-X segment (2: X at two rows)"));
  specs.push_back(
      choice_option("interp", {"plane", "seed"}, "plane",
                    "plane: perspective-correct planes of I and 1/Z; seed: eq. 3-4's I and Z at the segment "
                    "ends"));
  specs.push_back(samples_per_pixel_option(hls::kMaxSideLog2));
  specs.push_back(syntax_option("budget-ms", "off or MS > 0", check_budget, "off",
                                "the governor: the overload threshold lowered until the predicted field passes fit MS "
                                "(timing/segment_prediction.hpp)"));
  return specs;
}

const std::vector<DropKind>& segment_drop_kinds() {
  using Cause = DropKind::Cause;
  static const std::vector<DropKind> kinds{
      {"polygons_overload", Cause::kMemoryFull,
       "polygon(s) dropped by the overload threshold (the segment memory holds " +
           std::to_string(hls::kSegmentBankWords) + " segments a field)"},
      {"polygons_frame_memory_full", Cause::kMemoryFull,
       "polygon(s) did not fit the frame memory (" + std::to_string(hls::kFrameBankWords) + " words a bank)"},
      {"segments_segment_memory_full", Cause::kMemoryFull, "segment(s) did not fit the segment memory"}};
  return kinds;
}

std::unique_ptr<RasterEngine> make_segment_engine(const EngineOptions& options, bool twin) {
  const char* engine = segment_engine_declaration(twin).name;
  const EngineSettings s = parse_engine_options(engine, segment_engine_options(twin), options.params);
  const std::string format = twin ? "double" : s.text("format");
  const bool quad = s.is("x-rows", "2"), seed_interp = s.is("interp", "seed");
  const int side_log2 = s.side_log2();
  const double budget = budget_of(s);
  if (twin)
    return std::make_unique<SegmentEngine<DoubleSegmentArith>>(engine, "double", quad, seed_interp, side_log2,
                                                               options.threads, budget);
  if (format == "coarse")
    return std::make_unique<SegmentEngine<hls::FixedSegmentArith<hls::SegmentFormatCoarse>>>(
        engine, hls::SegmentFormatCoarse::name, quad, seed_interp, side_log2, options.threads, budget);
  if (format == "medium")
    return std::make_unique<SegmentEngine<hls::FixedSegmentArith<hls::SegmentFormatMedium>>>(
        engine, hls::SegmentFormatMedium::name, quad, seed_interp, side_log2, options.threads, budget);
  if (format == "fine")
    return std::make_unique<SegmentEngine<hls::FixedSegmentArith<hls::SegmentFormatFine>>>(
        engine, hls::SegmentFormatFine::name, quad, seed_interp, side_log2, options.threads, budget);
  throw std::logic_error("segment format " + format + " has no table row");
}

// Both engines' rows of `cig engines` (engine/engine_declaration.hpp).
const EngineDeclaration& segment_engine_declaration(bool twin) {
  EngineCapabilities fixed;
  fixed.bit_accurate = fixed.polygons = fixed.pipelines = fixed.formatter = true;
  static const EngineDeclaration kFixed{"segment",
                                        "stages C and D: the formatter (eq. 1) and seed 001's segment processor",
                                        fixed,
                                        [](const EngineOptions& o) { return make_segment_engine(o, false); },
                                        [] { return segment_engine_options(false); },
                                        segment_drop_kinds};
  static const EngineDeclaration kTwin{"segment-double",
                                       "stages C and D as `segment`, its kernels on double arithmetic (the twin)",
                                       twin_capabilities(fixed, kFixed.name),
                                       [](const EngineOptions& o) { return make_segment_engine(o, true); },
                                       [] { return segment_engine_options(true); },
                                       segment_drop_kinds};
  return twin ? kTwin : kFixed;
}

}  // namespace cig
