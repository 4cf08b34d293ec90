// Frame memory (SPEC D, seed 001): two banks of 16K words. The edge generator writes one frame's
// polygons (a header word and one word per stored edge) into one bank while the preprocessor reads
// the previous frame from the other; the banks swap at the frame pulse. A polygon that does not fit
// is not written, and counted: overflow is reported, never wrapped.
#pragma once

#include "hls/segment/segment_arith.hpp"
#include "hls/types/top_ports.hpp"

CIG_HLS_BEGIN_NAMESPACE

constexpr int kFrameBankWords = 16 * 1024;

template <class P>
struct FrameWord {
  bool is_header = false;
  PolygonHeader<P> header;  // when is_header
  Edge<P> edge;             // otherwise
};

template <class P, int kWords = kFrameBankWords>
struct FrameMemory {
  FrameWord<P> bank[2][kWords];
  int used[2] = {0, 0};
  int write_bank = 0;
  UInt<24> polygons_written, polygons_overflowed;
};

// Starts a frame in the write bank (the frame pulse: the other bank becomes readable).
template <class P, int K>
void frame_memory_swap(FrameMemory<P, K>& m) {
  m.write_bank ^= 1;
  m.used[m.write_bank] = 0;
  m.polygons_written = UInt<24>(0);
  m.polygons_overflowed = UInt<24>(0);
}

// Writes a polygon's header and edges; false (and counted) when the bank has no room for it.
template <class P, int K>
bool frame_memory_write(const PolygonEdges<P>& e, FrameMemory<P, K>& m) {
  const int b = m.write_bank;
  const int words = frame_memory_words(e);
  if (m.used[b] + words > K) {
    m.polygons_overflowed = UInt<24>(m.polygons_overflowed.value() + 1);
    return false;
  }
  int a = m.used[b];
  m.bank[b][a].is_header = true;
  m.bank[b][a].header = e.h;
  ++a;
  for (int k = 0; k < kMaxEdgesPerChain; ++k) {
    if (k >= int(e.h.left_count.value())) break;
    m.bank[b][a].is_header = false;
    m.bank[b][a].edge = e.left[k];
    ++a;
  }
  for (int k = 0; k < kMaxEdgesPerChain; ++k) {
    if (k >= int(e.h.right_count.value())) break;
    m.bank[b][a].is_header = false;
    m.bank[b][a].edge = e.right[k];
    ++a;
  }
  m.used[b] = a;
  m.polygons_written = UInt<24>(m.polygons_written.value() + 1);
  return true;
}

// Reads the polygon at word address `addr` of bank `b` and advances `addr`; false at the end.
template <class P, int K>
bool frame_memory_read(const FrameMemory<P, K>& m, int b, int& addr, PolygonEdges<P>& out) {
  if (addr >= m.used[b] || !m.bank[b][addr].is_header) return false;
  out.h = m.bank[b][addr].header;
  out.valid = true;
  ++addr;
  for (int k = 0; k < kMaxEdgesPerChain; ++k) {
    if (k >= int(out.h.left_count.value())) break;
    out.left[k] = m.bank[b][addr++].edge;
  }
  for (int k = 0; k < kMaxEdgesPerChain; ++k) {
    if (k >= int(out.h.right_count.value())) break;
    out.right[k] = m.bank[b][addr++].edge;
  }
  return true;
}

// Top function (HLS): one polygon into the write bank, default format.
// Ports (hls/types/top_ports.hpp): name, direction, interface, C++ type.
#define CIG_HLS_PORTS_frame_memory_write_top(PORT, ARRAY, RESULT) \
  RESULT(bool)                                                    \
  PORT(e, in, ap_none, const PolygonEdges<DefaultSegmentArith>&)  \
  PORT(m, inout, ap_memory, FrameMemory<DefaultSegmentArith>&)
inline CIG_HLS_TOP(frame_memory_write_top) { return frame_memory_write(e, m); }

CIG_HLS_END_NAMESPACE
