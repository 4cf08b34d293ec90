// Y sorter and segment memory (SPEC D, seed 001): a bucket sort by raster line that keeps, for
// each line, a linked list of its segments in arrival (= priority) order, with head pointers per
// line and a count per line. Even lines are stored in one bank, odd lines in the other (the two TV
// fields), 48K words each. A segment that finds its bank full is dropped and counted.
#pragma once

#include "hls/segment/overload.hpp"
#include "hls/segment/segment_arith.hpp"
#include "hls/types/top_ports.hpp"

CIG_HLS_BEGIN_NAMESPACE

constexpr int kNullPointer = -1;

template <class P, int kWords = kSegmentBankWords>
struct SegmentMemory {
  Segment<P> seg[2][kWords];
  int next[2][kWords];
  int used[2] = {0, 0};
  int head[kMaxLines], tail[kMaxLines];
  UInt<17> count[kMaxLines];  // segments per line (the video channel's load)
  UInt<24> dropped[2];        // segments lost to a full bank, per field
};

template <class P, int K>
void y_sorter_reset(SegmentMemory<P, K>& m, int lines) {
  m.used[0] = m.used[1] = 0;
  m.dropped[0] = m.dropped[1] = UInt<24>(0);
  for (int l = 0; l < kMaxLines; ++l) {
    if (l >= lines) break;
    m.head[l] = m.tail[l] = kNullPointer;
    m.count[l] = UInt<17>(0);
  }
}

// Appends a segment to its line's list (FIFO: priority order within the line is kept).
template <class P, int K>
bool y_sort(const Segment<P>& s, SegmentMemory<P, K>& m) {
  const int line = int(s.line.value());
  const int b = line & 1;
  if (m.used[b] >= K) {
    m.dropped[b] = UInt<24>(m.dropped[b].value() + 1);
    return false;
  }
  const int a = m.used[b]++;
  m.seg[b][a] = s;
  m.next[b][a] = kNullPointer;
  if (m.head[line] == kNullPointer) m.head[line] = a;
  else m.next[b][m.tail[line]] = a;
  m.tail[line] = a;
  m.count[line] = UInt<17>(m.count[line].value() + 1);
  return true;
}

// Ports (hls/types/top_ports.hpp): name, direction, interface, C++ type.
#define CIG_HLS_PORTS_y_sorter_top(PORT, ARRAY, RESULT)     \
  RESULT(bool)                                              \
  PORT(s, in, ap_none, const Segment<DefaultSegmentArith>&) \
  PORT(m, inout, ap_memory, SegmentMemory<DefaultSegmentArith>&)
inline CIG_HLS_TOP(y_sorter_top) { return y_sort(s, m); }

CIG_HLS_END_NAMESPACE
