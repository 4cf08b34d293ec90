// The Verilated configurations of rtl/quadtree/qt_raster.sv inside its co-simulation wrapper
// (qt_raster_cosim_tb.sv; verif/cosim/CMakeLists.txt verilates each with its own prefix, FST
// tracing compiled in) behind one interface (rtl_runner_impl.hpp).

// Verilator's headers and the generated ones are not ours to keep -Wextra-clean.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include "Vqt_raster_n6_t1.h"
#include "Vqt_raster_n6_t1_qt_raster_cosim_tb.h"
#include "Vqt_raster_n6_t2.h"
#include "Vqt_raster_n6_t2_qt_raster_cosim_tb.h"
#include "Vqt_raster_n9_t1.h"
#include "Vqt_raster_n9_t1_qt_raster_cosim_tb.h"
#include "Vqt_raster_n9_t2.h"
#include "Vqt_raster_n9_t2_qt_raster_cosim_tb.h"
#include "rtl_runner_impl.hpp"
#pragma GCC diagnostic pop

namespace cig::cosim {

using detail::RtlRunnerImpl;

std::vector<RtlConfig> rtl_configs() { return {{6, 1}, {6, 2}, {9, 1}, {9, 2}}; }

std::unique_ptr<RtlRunner> make_rtl_runner(int raster_log2, int tree_levels) {
  if (raster_log2 == 6 && tree_levels == 1)
    return std::make_unique<RtlRunnerImpl<Vqt_raster_n6_t1, Vqt_raster_n6_t1_qt_raster_cosim_tb>>(6);
  if (raster_log2 == 6 && tree_levels == 2)
    return std::make_unique<RtlRunnerImpl<Vqt_raster_n6_t2, Vqt_raster_n6_t2_qt_raster_cosim_tb>>(6);
  if (raster_log2 == 9 && tree_levels == 1)
    return std::make_unique<RtlRunnerImpl<Vqt_raster_n9_t1, Vqt_raster_n9_t1_qt_raster_cosim_tb>>(9);
  if (raster_log2 == 9 && tree_levels == 2)
    return std::make_unique<RtlRunnerImpl<Vqt_raster_n9_t2, Vqt_raster_n9_t2_qt_raster_cosim_tb>>(9);
  return nullptr;
}

}  // namespace cig::cosim
