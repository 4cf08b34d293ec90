// Multilevel priority masks (SPEC E, seed 004): polygons arrive front to back; every window of
// levels 0..n-1 keeps a 4-bit mask, one bit per child. A bit is set when its child is wholly
// covered by one opaque polygon (the PE's full-coverage test), when the child is a pixel whose
// sub-pixel mask became full (the pixel processor), or when all four bits of the child's own mask
// are set (fed back upward). A PE skips every child whose bit is set, so polygons hidden behind
// what is already drawn die at the coarsest level where that is known.
//
// Storage: level l holds 4^l words, word (x, y) at index base(l) + y 2^l + x, base(l) =
// (4^l - 1) / 3; (4^10 - 1) / 3 = 349,525 words for N = 1024.
//
// Timing contract (the architecture model and the RTL): reads see the masks as they were at the
// start of the cycle; every set of a cycle, with its upward closure, takes effect at the clock
// edge. The closure of a set of bit-sets does not depend on their order (OR is commutative and the
// "all four set" rule is monotone), so one cycle's sets can be applied in any order.
#pragma once

#include "hls/quadtree/records.hpp"
#include "hls/types/top_ports.hpp"

CIG_HLS_BEGIN_NAMESPACE

constexpr int kMaskWords = ((1 << (2 * kQuadMaxLevels)) - 1) / 3;

struct MaskMemory {
  UInt<4> word[kMaskWords];
};

inline int mask_base(int level) { return ((1 << (2 * level)) - 1) / 3; }
inline int mask_index(int level, int x, int y) { return mask_base(level) + (y << level) + x; }

// Clears the words of levels 0..n-1 (the frame's start).
inline void mask_clear(MaskMemory& m, int raster_log2) {
  const int words = mask_base(raster_log2);
  for (int k = 0; k < kMaskWords; ++k) {
    if (k >= words) break;
    m.word[k] = UInt<4>(0);
  }
}

inline UInt<4> mask_read(const MaskMemory& m, int level, int x, int y) { return m.word[mask_index(level, x, y)]; }

// Sets bit q of word (level, x, y) and feeds full words upward. Returns the number of words that
// became full (statistics). Windows of level 0..kQuadMaxLevels - 1 have words; a request for
// another level sets nothing, and x, y keep their low `level` bits (the address lines a word of
// that level has), so no request reaches outside the memory.
inline int mask_set(MaskMemory& m, int level, int x, int y, int q) {
  int became_full = 0;
  if (level < 0 || level >= kQuadMaxLevels) return 0;
  int l = level, wx = x & ((1 << level) - 1), wy = y & ((1 << level) - 1), bit = q & 3;
  for (int step = 0; step < kQuadMaxLevels; ++step) {
    if (l < 0) break;
    const int idx = mask_index(l, wx, wy);
    const UInt<4> old = m.word[idx];
    const UInt<4> now = UInt<4>(old.value() | (1u << bit));
    m.word[idx] = now;
    if (now.value() != 0xFu || old.value() == 0xFu) break;
    ++became_full;
    bit = ((wy & 1) << 1) | (wx & 1);  // this window's position in its parent
    wx >>= 1;
    wy >>= 1;
    --l;
  }
  return became_full;
}

// Top function (HLS): one set request (level, address, child) with its upward closure.
// Ports (hls/types/top_ports.hpp): name, direction, interface, C++ type.
#define CIG_HLS_PORTS_mask_memory_top(PORT, ARRAY, RESULT) \
  RESULT(UInt<5>)                                          \
  PORT(m, inout, ap_memory, MaskMemory&)                   \
  PORT(level, in, ap_none, UInt<4>)                        \
  PORT(x, in, ap_none, UInt<10>)                           \
  PORT(y, in, ap_none, UInt<10>)                           \
  PORT(child, in, ap_none, UInt<2>)
inline CIG_HLS_TOP(mask_memory_top) {
  return UInt<5>(mask_set(m, int(level.value()), int(x.value()), int(y.value()), int(child.value())));
}

CIG_HLS_END_NAMESPACE
