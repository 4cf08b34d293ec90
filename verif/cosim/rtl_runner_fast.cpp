// The benchmark's Verilated configurations (bench_rtl): the co-simulation's RTL and wrapper
// Verilated for speed (verif/cosim/CMakeLists.txt, cig_rtl_bench_models: no tracing, no
// assertions, the generated code at -O2), behind the same runners (quadtree/rtl_runner_impl.hpp,
// invparam/ip_rtl_runner_impl.hpp): the quadtree's 9p and 7p2t, the inverse-parameter array for
// the seed's 64-bit word (80-bit registers), N_PP = 64.

// Verilator's headers and the generated ones are not ours to keep -Wextra-clean.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include "Vip_array_fast_w64_n64.h"
#include "Vip_array_fast_w64_n64_ip_array_cosim_tb.h"
#include "Vqt_raster_fast_n9_t1.h"
#include "Vqt_raster_fast_n9_t1_qt_raster_cosim_tb.h"
#include "Vqt_raster_fast_n9_t2.h"
#include "Vqt_raster_fast_n9_t2_qt_raster_cosim_tb.h"
#include "invparam/ip_rtl_runner_impl.hpp"
#include "quadtree/rtl_runner_impl.hpp"
#pragma GCC diagnostic pop

namespace cig::cosim {

std::unique_ptr<RtlRunner> make_fast_rtl_runner(int raster_log2, int tree_levels) {
  using detail::RtlRunnerImpl;
  if (raster_log2 == 9 && tree_levels == 1)
    return std::make_unique<RtlRunnerImpl<Vqt_raster_fast_n9_t1, Vqt_raster_fast_n9_t1_qt_raster_cosim_tb, false>>(9);
  if (raster_log2 == 9 && tree_levels == 2)
    return std::make_unique<RtlRunnerImpl<Vqt_raster_fast_n9_t2, Vqt_raster_fast_n9_t2_qt_raster_cosim_tb, false>>(9);
  return nullptr;
}

std::unique_ptr<IpRtl> make_fast_ip_rtl(int w, int n_pp) {
  if (w == 64 && n_pp == 64)
    return std::make_unique<
        detail::IpRtlImpl<Vip_array_fast_w64_n64, Vip_array_fast_w64_n64_ip_array_cosim_tb, false>>();
  return nullptr;
}

}  // namespace cig::cosim
