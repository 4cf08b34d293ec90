// Stage D in time: a cycle model of seed 001's segment processor (the PGS) and its video channel,
// fed by what the HLS kernels produced for the frame (SegmentLoad: the frame memory's polygons in
// the order the preprocessor reads them, their edges and segments per field, the light points'
// coding-table segments, and each raster line's stored segments).
//
// The machine (seed 001, figure 1), as this model times it:
//   edge generator   polygons' edges into the frame memory's write bank, at the vertex input rate:
//                    "not more than 10 us per edge"; it runs beside stage B on frame k+1 (front_ns).
//   frame memory     two banks of 16K words, swapped at the frame pulse.
//   per field pass   the segment memory has one bank per field (48K words each, switched with the
//                    field scan): field f's segments are generated into its bank during the field
//                    slot before the field is shown, one pass over the frame memory's read bank.
//                    48K segments x 400 ns = 19.7 ms: a bank fills within one 20 ms field.
//     preprocessor   reads each record (header + edge words) at one word per clock (100 ns);
//                    a polygon above the overload threshold costs its header only.
//     segment gen.   the pipelined I/Z multiplier-divider (100 ns clock) gives one result of
//                    eq. 3-4 per clock: I and Z at both ends, 4 clocks per polygon segment; a light
//                    point's segments come from the coding table, 1 clock each.
//     Y sorter       each segment written into the segment memory, 400 ns (the seed's average).
//   video channel    reads a line's segments at 200 ns each into the free one of two line buffers
//                    while the line before is shown; the line must be read when the beam reaches it.
// Queues between units have stated depths (SegmentTimingParams); a unit whose output queue is full
// stalls. Every figure is in ns of model time.
//
// The rules (segment_cycle_model.cpp), per field f and part, from the pass start at 0:
//   preprocessor     record i costs clock_ns x words (header_words + edges; header_words if dropped;
//                    light_words for a light); it holds record i until a slot of the preprocessor
//                    queue is free (the generator has taken record i - preprocessor_queue; with a
//                    depth of 0, until the generator takes record i), then starts record i + 1.
//   segment gen.     takes record i when it is queued and record i - 1 is done; each of its
//                    segments[f] segments costs clock_ns x iz_clocks (light_clocks for a light), then
//                    enters the segment queue once the sorter has taken segment j - segment_queue.
//                    A dropped record, or one with no segments in field f, passes at no cost.
//   Y sorter         takes the queued segments in order, write_ns each.
//   pass             ends when the last record has been read and the last segment written.
//   video            line k of field f (raster line 2k + f) is shown from field_ns + blanking_ns +
//                    k x line_ns; its read (sum over parts of its segments x read_ns) starts when
//                    every part has written it (line_last_item's last write), the line before is read
//                    and a buffer is free (line k - line_buffers has been shown). A read that would
//                    end after the line's display start is an underrun: the reader stops there, the
//                    unread segments (ceil(unread time / read_ns), at least 1) are not shown, and the
//                    next line's read may start from that display start.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace cig {

// One record of the frame memory, in the order the preprocessor reads it (the Y sorter's order:
// light points interleaved by priority as generate_and_sort emits them).
struct SegmentLoadItem {
  std::uint32_t edges = 0;             // edge words (left + right); 0 for a light point
  std::uint32_t segments[2] = {0, 0};  // segments written on even / odd raster lines
  bool light = false;                  // a light point: coding-table segments, never dropped
  bool dropped = false;                // above the overload threshold: header read, no segments
};

// What one rendering pipeline's segment processor did with one channel's frame.
struct SegmentLoad {
  int raster_lines = 0;            // n: lines 0, 2, 4, ... are field 0, lines 1, 3, ... field 1
  std::uint64_t edges_formed = 0;  // edges the edge generator wrote (every polygon, dropped or not)
  std::vector<SegmentLoadItem> items;
  std::vector<std::uint32_t> line_segments;  // per raster line: segments stored in the segment memory
  std::vector<std::int32_t> line_last_item;  // per raster line: the item that wrote its last segment, or -1
};

// Parameters; every default is the seed's figure or a stated assumption (A:).
struct SegmentTimingParams {
  double clock_ns = 100;             // seed 001: the I/Z multiplier-divider's clock
  double edge_ns = 10000;            // seed 001: edge formation, at most 10 us per edge
  int header_words = 1;              // A: a polygon record's header, one word per clock
  int light_words = 2;               // A: a light point's record (centre, diameter + colour)
  int iz_clocks_per_segment = 4;     // eq. 3-4: I_l, I_r, Z_l, Z_r, one result per clock
  int light_clocks_per_segment = 1;  // A: one coding-table read per light segment
  double write_ns = 400;             // seed 001: segment written into the segment memory (average)
  double read_ns = 200;              // seed 001: segment read by the video channel
  int preprocessor_queue = 4;        // A: records between preprocessor and segment generator
  int segment_queue = 16;            // A: segments between segment generator and Y sorter
  int line_buffers = 2;              // A: the video channel's line buffers (one filled, one shown)
  double field_ns = 20e6;            // seed 001: a TV field, 20 ms (625 lines, 50 fields/s)
  double blanking_ns = 1.6e6;        // A: 625/50 vertical blanking, 25 lines of 64 us
  // The raster's n/2 lines of a field share the active field time: line period
  // (field_ns - blanking_ns) / (n/2); 71.9 us at n = 512.
  double line_ns(int raster_lines) const;
};

// One unit's time in a pass: busy (working), stalled (done but its output queue full), starved
// (waiting for input); busy + stalled + starved = the pass time.
struct UnitTime {
  double busy_ns = 0, stalled_ns = 0, starved_ns = 0;
};

struct FieldTiming {
  double pass_ns = 0;  // the field's pass: first record read to last segment written (slowest part)
  UnitTime preprocessor, generator, sorter;  // the slowest part's (the first one on a tie)
  double video_busy_ns = 0;                  // segments read x read_ns
  std::uint64_t segments = 0;                // written in this field
  std::uint64_t underrun_lines = 0;          // lines not read in full when the beam reached them
  std::uint64_t segments_not_shown = 0;      // segments of those lines the video channel had no time for
  double worst_line_slack_ns = 0;            // min over lines of (display start - read finish); < 0: underrun
  std::uint64_t read_bound_underruns = 0;    // underruns the read time alone causes (late even if ready at 0)
};

struct SegmentFrameTiming {
  double front_ns = 0;  // edge generator: edges_formed x edge_ns (beside stage B)
  FieldTiming field[2];
  double back_ns = 0;        // field[0].pass_ns + field[1].pass_ns
  bool fits_fields = false;  // every pass within field_ns and no underrun
  // "video channel" if a line underran on its read time alone; else "preprocessor", "segment generator" or
  // "Y sorter": the one with the most busy time in the slower pass (first in that order on a tie); "" if empty.
  std::string limiting_unit;
  std::uint64_t underrun_lines = 0;
};

// The frame's stage D timing; parts: one load per rendering pipeline (seed 000's Nc), each with its
// own segment processor, all read by one video channel (a line's read time is the sum over parts,
// ready when every part has written it). The parts run in parallel: front_ns and each pass are the
// maximum over parts, segments their sum. The parts' raster_lines must agree and every line vector be
// raster_lines long, line_last_item naming a record or -1, else std::invalid_argument (so do negative
// costs or queue depths, no line buffer, or no active field time). No parts: every figure zero.
SegmentFrameTiming time_segment_frame(const std::vector<SegmentLoad>& parts, const SegmentTimingParams& p = {});

}  // namespace cig
