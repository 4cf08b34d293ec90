// Build configuration of the hls/ layer.
//
// Native build: the type layer stores plain 64-bit integers. With -DCIG_HLS_SYSTEMC it stores
// SystemC's sc_dt::sc_int / sc_uint. Everything in hls/ lives in an inline namespace named after
// the configuration, so a program may link both configurations (the C model built natively with
// a SystemC-typed test) without two different definitions of one name.
#pragma once

#ifdef CIG_HLS_SYSTEMC
#define CIG_HLS_ABI systemc_types
#else
#define CIG_HLS_ABI native_types
#endif

#define CIG_HLS_BEGIN_NAMESPACE \
  namespace cig {               \
  namespace hls {               \
  inline namespace CIG_HLS_ABI {
#define CIG_HLS_END_NAMESPACE \
  }                           \
  }                           \
  }
