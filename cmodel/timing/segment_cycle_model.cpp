// Stage D in time: seed 001's segment processor (preprocessor -> segment generator -> Y sorter) and
// its video channel as a deterministic discrete-event model; every event time is a max/plus of the
// ones before it, so a pass costs O(records + segments) and the video O(lines x parts).
#include "timing/segment_cycle_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cig {

double SegmentTimingParams::line_ns(int raster_lines) const {
  if (raster_lines <= 0) return 0;
  return (field_ns - blanking_ns) / (raster_lines / 2.0);
}

namespace {

// One part's pass over its frame memory for one field.
struct PartPass {
  double pass_ns = 0;
  UnitTime preprocessor, generator, sorter;
  std::uint64_t segments = 0;
  std::vector<double> item_done;  // per record: its last segment written (or when it passed the generator)
};

void check_params(const SegmentTimingParams& p) {
  if (p.clock_ns < 0 || p.edge_ns < 0 || p.write_ns < 0 || p.read_ns < 0 || p.header_words < 0 || p.light_words < 0 ||
      p.iz_clocks_per_segment < 0 || p.light_clocks_per_segment < 0)
    throw std::invalid_argument("segment timing: negative cost");
  if (p.preprocessor_queue < 0 || p.segment_queue < 0) throw std::invalid_argument("segment timing: negative queue");
  if (p.line_buffers < 1) throw std::invalid_argument("segment timing: the video channel needs a line buffer");
  if (p.blanking_ns < 0 || p.field_ns <= p.blanking_ns)
    throw std::invalid_argument("segment timing: the field has no active time");
}

// The caller fills the line vectors from the segment memory: one entry per raster line, items by index.
void check_parts(const std::vector<SegmentLoad>& parts) {
  const int n = parts.front().raster_lines;
  if (n < 0) throw std::invalid_argument("segment timing: negative raster_lines");
  for (const SegmentLoad& load : parts) {
    if (load.raster_lines != n) throw std::invalid_argument("segment timing: parts' raster_lines differ");
    const std::size_t lines = static_cast<std::size_t>(n);
    if (load.line_segments.size() != lines || load.line_last_item.size() != lines)
      throw std::invalid_argument("segment timing: line vectors are not raster_lines long");
    for (std::int32_t item : load.line_last_item)
      if (item < -1 || item >= static_cast<std::int64_t>(load.items.size()))
        throw std::invalid_argument("segment timing: line_last_item names no record");
  }
}

// Words the preprocessor reads for a record: a dropped polygon (above the overload threshold) is
// recognised from its header alone; a light point is never dropped.
double record_words(const SegmentLoadItem& item, const SegmentTimingParams& p) {
  if (item.light) return p.light_words;
  if (item.dropped) return p.header_words;
  return static_cast<double>(p.header_words) + item.edges;
}

std::uint32_t written_segments(const SegmentLoadItem& item, int field) {
  return (item.dropped && !item.light) ? 0 : item.segments[field];
}

// The pass over one part's frame memory for field f. Queue rules:
//  - preprocessor queue (Q records): having read record i, the preprocessor holds it until a slot is
//    free, i.e. until the generator has taken record i - Q (Q = 0: until the generator takes record
//    i itself); that hold is its stalled time, and only then does it start reading record i + 1.
//  - segment queue (S segments): a segment computed by the generator enters the queue once the Y
//    sorter has taken segment j - S (S = 0: when the sorter takes it); the wait is the generator's
//    stalled time and the generator starts the next segment only after the hand-over.
PartPass run_pass(const SegmentLoad& load, int f, const SegmentTimingParams& p) {
  PartPass r;
  const std::size_t records = load.items.size();
  const std::size_t Q = static_cast<std::size_t>(p.preprocessor_queue);
  const std::size_t S = static_cast<std::size_t>(p.segment_queue);
  r.item_done.assign(records, 0);
  std::vector<double> taken(records, 0);                            // when the generator took each record
  std::vector<double> sorter_took(std::max<std::size_t>(S, 1), 0);  // ring: last S segments' take times
  double reader_free = 0, generator_free = 0, sorter_free = 0;
  std::uint64_t j = 0;  // the field's segment index (the Y sorter's order)
  for (std::size_t i = 0; i < records; ++i) {
    const SegmentLoadItem& item = load.items[i];
    const double read = p.clock_ns * record_words(item, p);
    const double read_done = reader_free + read;
    double queued = read_done, take = 0;
    if (Q == 0) {
      queued = take = std::max(read_done, generator_free);
    } else {
      if (i >= Q) queued = std::max(read_done, taken[i - Q]);
      take = std::max(queued, generator_free);
    }
    r.preprocessor.busy_ns += read;
    r.preprocessor.stalled_ns += queued - read_done;
    reader_free = queued;
    taken[i] = take;
    // eq. 3-4: I and Z at both ends, one multiplier-divider result per clock; lights from the coding table.
    const double compute = p.clock_ns * (item.light ? p.light_clocks_per_segment : p.iz_clocks_per_segment);
    const std::uint32_t segments = written_segments(item, f);
    double t = take;
    for (std::uint32_t s = 0; s < segments; ++s, ++j) {
      const double computed = t + compute;
      double put = computed;
      if (S == 0) put = std::max(computed, sorter_free);
      else if (j >= S) put = std::max(computed, sorter_took[j % S]);
      const double sorter_take = std::max(put, sorter_free);
      sorter_free = sorter_take + p.write_ns;  // written into field f's bank of the segment memory
      if (S > 0) sorter_took[j % S] = sorter_take;
      r.generator.busy_ns += compute;
      r.generator.stalled_ns += put - computed;
      r.sorter.busy_ns += p.write_ns;
      t = put;
    }
    generator_free = t;
    r.item_done[i] = segments ? sorter_free : take;
    r.segments += segments;
  }
  // The pass ends when the last record has been read and the last segment written.
  r.pass_ns = std::max(reader_free, sorter_free);
  for (UnitTime* u : {&r.preprocessor, &r.generator, &r.sorter}) u->starved_ns = r.pass_ns - u->busy_ns - u->stalled_ns;
  return r;
}

// Field f's lines through the video channel: line k (raster line 2k + f) is shown from
// display_k = field_ns + blanking_ns + k x line_ns after its pass began (the pass runs in the slot
// before); its read into a line buffer starts when every part has written it, the read before has
// finished and a buffer is free (the line B lines back has been shown: display_{k-B+1}).
void time_video(const std::vector<SegmentLoad>& parts, const std::vector<PartPass>& passes, int f,
                const SegmentTimingParams& p, FieldTiming& ft) {
  const int n = parts.front().raster_lines;
  const double line = p.line_ns(n), first = p.field_ns + p.blanking_ns;
  const int B = p.line_buffers;
  double reader_free = 0, worst = std::numeric_limits<double>::infinity();
  int k = 0;
  for (int l = f; l < n; l += 2, ++k) {
    double ready = 0;
    std::uint64_t segments = 0;
    for (std::size_t q = 0; q < parts.size(); ++q) {
      segments += parts[q].line_segments[l];
      const std::int32_t item = parts[q].line_last_item[l];
      if (item >= 0) ready = std::max(ready, passes[q].item_done[item]);
    }
    const double read = segments * p.read_ns, display = first + k * line;
    const double buffer_free = k >= B ? first + (k - B + 1) * line : 0;
    const double earliest = std::max(reader_free, buffer_free);
    const double finish = std::max(ready, earliest) + read;
    worst = std::min(worst, display - finish);
    if (segments == 0 || finish <= display) {
      ft.video_busy_ns += read;
      reader_free = finish;
      continue;
    }
    // Underrun: the beam reaches the line first; the reader stops there and what it missed is not shown.
    const double unread = std::min(read, finish - display);
    std::uint64_t lost = segments;
    if (p.read_ns > 0) lost = static_cast<std::uint64_t>(std::max(1.0, std::ceil(unread / p.read_ns - 1e-9)));
    lost = std::min(lost, segments);
    ft.underrun_lines += 1;
    ft.segments_not_shown += lost;
    if (earliest + read > display) ft.read_bound_underruns += 1;  // late even if written at once
    ft.video_busy_ns += (segments - lost) * p.read_ns;
    reader_free = display;
  }
  ft.worst_line_slack_ns = k > 0 ? worst : 0;
}

// Field f over every part: the parts' segment processors run in parallel, so the pass is the
// slowest part's; the unit times are that part's (the first such part on a tie).
FieldTiming time_field(const std::vector<SegmentLoad>& parts, int f, const SegmentTimingParams& p) {
  std::vector<PartPass> passes;
  passes.reserve(parts.size());
  for (const SegmentLoad& load : parts) passes.push_back(run_pass(load, f, p));
  FieldTiming ft;
  std::size_t slowest = 0;
  for (std::size_t q = 0; q < passes.size(); ++q) {
    ft.segments += passes[q].segments;
    if (passes[q].pass_ns > passes[slowest].pass_ns) slowest = q;
  }
  ft.pass_ns = passes[slowest].pass_ns;
  ft.preprocessor = passes[slowest].preprocessor;
  ft.generator = passes[slowest].generator;
  ft.sorter = passes[slowest].sorter;
  time_video(parts, passes, f, p, ft);
  return ft;
}

// The video channel if a line underran on its read time alone; else the unit with the most busy
// time in the slower pass (preprocessor, generator, sorter order on a tie); empty for an empty pass.
std::string limiting_unit(const SegmentFrameTiming& t) {
  if (t.field[0].read_bound_underruns + t.field[1].read_bound_underruns > 0) return "video channel";
  const FieldTiming& slow = t.field[1].pass_ns > t.field[0].pass_ns ? t.field[1] : t.field[0];
  if (slow.pass_ns <= 0) return "";
  std::string unit = "preprocessor";
  double most = slow.preprocessor.busy_ns;
  if (slow.generator.busy_ns > most) unit = "segment generator", most = slow.generator.busy_ns;
  if (slow.sorter.busy_ns > most) unit = "Y sorter";
  return unit;
}

}  // namespace

SegmentFrameTiming time_segment_frame(const std::vector<SegmentLoad>& parts, const SegmentTimingParams& p) {
  SegmentFrameTiming t;
  if (parts.empty()) return t;
  check_params(p);
  check_parts(parts);
  // Each part has its own edge generator, all beside stage B on the next frame.
  for (const SegmentLoad& load : parts) t.front_ns = std::max(t.front_ns, load.edges_formed * p.edge_ns);
  for (int f = 0; f < 2; ++f) t.field[f] = time_field(parts, f, p);
  t.back_ns = t.field[0].pass_ns + t.field[1].pass_ns;
  t.underrun_lines = t.field[0].underrun_lines + t.field[1].underrun_lines;
  t.fits_fields = t.field[0].pass_ns <= p.field_ns && t.field[1].pass_ns <= p.field_ns && t.underrun_lines == 0;
  t.limiting_unit = limiting_unit(t);
  return t;
}

}  // namespace cig
