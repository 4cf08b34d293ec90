// The runner of the mutation test's Verilated models (CMakeLists.txt here, build_models.sh): the
// co-simulation's runner (verif/cosim/quadtree/rtl_runner_impl.hpp) over the configurations of the
// mutated RTL copy that this build has, 6p and / or 4p2t (N = 64), without FST tracing. A
// configuration the mutant does not name is absent: rtl_configs() leaves it out and
// make_rtl_runner gives nullptr.

// Verilator's headers and the generated ones are not ours to keep -Wextra-clean.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#if __has_include("Vqt_raster_n6_t1.h")
#include "Vqt_raster_n6_t1.h"
#include "Vqt_raster_n6_t1_qt_raster_cosim_tb.h"
#define CIG_MUTANT_6P 1
#endif
#if __has_include("Vqt_raster_n6_t2.h")
#include "Vqt_raster_n6_t2.h"
#include "Vqt_raster_n6_t2_qt_raster_cosim_tb.h"
#define CIG_MUTANT_4P2T 1
#endif
#include "quadtree/rtl_runner_impl.hpp"
#pragma GCC diagnostic pop

namespace cig::cosim {

using detail::RtlRunnerImpl;

std::vector<RtlConfig> rtl_configs() {
  std::vector<RtlConfig> c;
#ifdef CIG_MUTANT_6P
  c.push_back({6, 1});
#endif
#ifdef CIG_MUTANT_4P2T
  c.push_back({6, 2});
#endif
  return c;
}

std::unique_ptr<RtlRunner> make_rtl_runner(int raster_log2, int tree_levels) {
#ifdef CIG_MUTANT_6P
  if (raster_log2 == 6 && tree_levels == 1)
    return std::make_unique<RtlRunnerImpl<Vqt_raster_n6_t1, Vqt_raster_n6_t1_qt_raster_cosim_tb, false>>(6);
#endif
#ifdef CIG_MUTANT_4P2T
  if (raster_log2 == 6 && tree_levels == 2)
    return std::make_unique<RtlRunnerImpl<Vqt_raster_n6_t2, Vqt_raster_n6_t2_qt_raster_cosim_tb, false>>(6);
#endif
  (void)raster_log2;
  (void)tree_levels;
  return nullptr;
}

}  // namespace cig::cosim
