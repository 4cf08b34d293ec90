// Access to the ports of a Verilated model of any width, LSB first (Verilator 5: ports up to 64
// bits are integers, wider ones VlWide<N> arrays of 32-bit words; the model declares its ports as
// references). Shared by the co-simulation's runner and the RTL unit tests.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include <verilated.h>

#include "record_bits.hpp"

namespace cig::cosim {

// The value type of a port (for casts: decltype of a port is a reference).
template <class Port>
using port_value_t = std::remove_reference_t<Port>;

template <class T>
std::uint64_t port_field(const T& v, int lo, int width) {
  return (std::uint64_t(v) >> lo) & (width >= 64 ? ~0ull : (1ull << width) - 1);
}
// width <= 64, a piece of a word at a time.
template <std::size_t N>
std::uint64_t port_field(const VlWide<N>& v, int lo, int width) {
  std::uint64_t r = 0;
  for (int b = 0; b < width;) {
    const int i = lo + b, take = std::min(32 - (i & 31), width - b);
    const std::uint64_t piece = std::uint64_t(v[std::size_t(i >> 5)] >> (i & 31));
    r |= (piece & ((1ull << take) - 1)) << b;
    b += take;
  }
  return r;
}
template <class T>
bool port_bit(const T& v, int i) {
  return port_field(v, i, 1) != 0;
}

template <class T>
void set_port_field(T& v, int lo, int width, std::uint64_t x) {
  const std::uint64_t m = (width >= 64 ? ~0ull : (1ull << width) - 1) << lo;
  v = T((std::uint64_t(v) & ~m) | ((x << lo) & m));
}
template <std::size_t N>
void set_port_field(VlWide<N>& v, int lo, int width, std::uint64_t x) {
  for (int b = 0; b < width; ++b) {
    const std::uint32_t m = 1u << ((lo + b) & 31);
    if ((x >> b) & 1u) v[std::size_t((lo + b) >> 5)] |= m;
    else v[std::size_t((lo + b) >> 5)] &= ~m;
  }
}

// Words of up to 128 bits (stage F's 73- and 80-bit registers), LSB first, in one integer: the
// same calls for a port of up to 64 bits and for a VlWide one.
__extension__ typedef unsigned __int128 PortWord;

// `width` (<= 128) bits of a port from bit `lo`.
template <class T>
PortWord port_word(const T& v, int lo, int width) {
  return port_field(v, lo, std::min(width, 64));  // a port of at most 64 bits
}
template <std::size_t N>
PortWord port_word(const VlWide<N>& v, int lo, int width) {
  if (width <= 64) return port_field(v, lo, width);
  return PortWord(port_field(v, lo, 64)) | PortWord(port_field(v, lo + 64, width - 64)) << 64;
}
// A whole port of `width` bits from the low bits of x (the rest of x is ignored).
template <class T>
void set_port_word(T& v, int width, PortWord x) {
  set_port_field(v, 0, std::min(width, 64), std::uint64_t(x));
}
template <std::size_t N>
void set_port_word(VlWide<N>& v, int width, PortWord x) {
  set_port_field(v, 0, std::min(width, 64), std::uint64_t(x));
  if (width > 64) set_port_field(v, 64, width - 64, std::uint64_t(x >> 64));
}

// A whole wide port from the first `width` bits of a record (the rest zero).
template <std::size_t N>
void set_port_bits(VlWide<N>& v, const Bits& b, int width) {
  for (std::size_t k = 0; k < N; ++k) v[k] = 0;
  for (int i = 0; i < width; ++i)
    if (b.get(i, 1)) v[std::size_t(i >> 5)] |= 1u << (i & 31);
}
// `width` bits of a port from bit `lo`.
template <std::size_t N>
Bits port_bits(const VlWide<N>& v, int lo, int width) {
  Bits b;
  b.load(v.data(), lo, width);
  return b;
}
template <class T>
Bits port_bits(const T& v, int lo, int width) {
  Bits b(width);
  b.put(0, width, port_field(v, lo, width));
  return b;
}

}  // namespace cig::cosim
