// The scene manager's per-channel setup (SPEC A.1, seed 000: "calculating the matrix B" is the
// host's; this is the one constant the visibility test derives from the channel): the length of
// the side planes' normals, s = sqrt(1 + t^2), rounded UP to 2^-16 (SideNorm), so that a side
// plane's threshold r * s can only grow (towards "visible").
//
//   t = T * 2^-16 (T: UInt<18>)  ->  Q = 2^32 + T^2 = (1 + t^2) * 2^32 (UInt<37>, exact)
//   S = ceil(sqrt(Q))            ->  s_q = S * 2^-16 >= sqrt(1 + t^2) > s_q - 2^-16
//
// The square root is the digit-by-digit (restoring) method, two radicand bits per step, shifts,
// one subtract and one compare per step: 19 steps for the 38-bit padded Q, no multiplier. It runs
// once per channel and frame, so the per-object path (visibility.hpp) has no square root.
// Exhaustively checked for every T in verif/kernels/test_manager_kernel.cpp.
#pragma once

#include "hls/manager/records.hpp"
#include "hls/types/top_ports.hpp"

CIG_HLS_BEGIN_NAMESPACE

namespace manager_detail {

// ceil(sqrt(q)) of q < 2^38. After step i (19 - i bits of the root formed) root < 2^(19 - i) and
// 0 <= rem = (top bits of q) - root^2 <= 2 root, so rem < 2^20 and UInt<21> never drops a bit.
inline UInt<20> ceil_sqrt(const UInt<38>& q) {
  UInt<19> root(0);
  UInt<21> rem(0);
  for (int i = 18; i >= 0; --i) {
    const UInt<2> pair = (q >> (2 * i)).slice<1, 0>();  // the next two radicand bits
    const UInt<23> cur = shl<2>(rem) | pair;            // rem * 4 + pair
    const UInt<21> trial = shl<2>(root) | UInt<1>(1);   // 4 root + 1 = (2 root + 1)^2 - (2 root)^2
    const bool take = cur >= trial;
    rem = wrap_unsigned<21>(take ? (cur - trial) : to_signed(cur));  // 0 <= value <= 2 root': exact
    root = wrap_unsigned<19>(shl<1>(root) | UInt<1>(take ? 1 : 0));  // root < 2^(19 - i): exact
  }
  return root + UInt<1>(rem != UInt<1>(0) ? 1 : 0);  // floor(sqrt(q)) + (q not a square)
}

}  // namespace manager_detail

// Ports (hls/types/top_ports.hpp): name, direction, interface, C++ type.
#define CIG_HLS_PORTS_manager_channel_setup_top(PORT, ARRAY, RESULT) \
  RESULT(void)                                                       \
  PORT(in, in, ap_none, const ManagerChannel&)                       \
  PORT(out, out, ap_vld, ManagerChannelSetup&)
inline CIG_HLS_TOP(manager_channel_setup_top) {
  const UInt<18> t = in.tan_half_fov.raw();
  const UInt<37> q = t * t + UInt<34>(std::uint64_t{1} << 32);  // (1 + t^2) * 2^32, exact
  // S <= ceil(sqrt(2^32 + (2^18 - 1)^2)) = 270,211 < 2^19: the narrowing keeps every bit.
  const UInt<19> s = wrap_unsigned<19>(manager_detail::ceil_sqrt(q));
  out.channel = in;
  out.side_norm = SideNorm::from_raw(s);
}

CIG_HLS_END_NAMESPACE
