// The verification stall pattern shared by the co-simulations of both raster processors: whether
// a port stalls in a given cycle is a hash of (seed, cycle, stream), so the architecture models
// and the RTL harnesses draw the same stalls without sharing state.
#pragma once

#include <cstdint>

namespace cig {

// True in `percent` % of the cycles (0: never).
inline bool stall_hit(std::uint32_t seed, std::uint64_t cycle, std::uint32_t stream, int percent) {
  if (percent <= 0) return false;
  std::uint64_t x =
      (std::uint64_t(seed) << 32) ^ (cycle * 0x9E3779B97F4A7C15ull) ^ (std::uint64_t(stream) * 0xD1B54A32D192ED03ull);
  x ^= x >> 30;
  x *= 0xBF58476D1CE4E5B9ull;
  x ^= x >> 27;
  x *= 0x94D049BB133111EBull;
  x ^= x >> 31;
  return int(x % 100u) < percent;
}

}  // namespace cig
