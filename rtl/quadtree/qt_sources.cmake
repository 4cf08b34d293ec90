# The quadtree RTL's source files (rtl/quadtree/) in compile order (the package first: yosys and
# Verilator read qt_pkg before the modules that name it): the one list that every consumer uses,
# CIG_RTL_SV (absolute paths). verif/rtl (lint, Verilated unit tests), verif/cosim (Verilated
# architectures) and tools/synth_report.sh (which reads the names below) all take it from here.
# The package, then the modules by name (a module may be named before it is read).
set(CIG_RTL_SV_NAMES
  qt_pkg.sv
  qt_e8m7_code.sv
  qt_fifo.sv
  qt_mask_memory.sv
  qt_pe.sv
  qt_pixel_lane.sv
  qt_pixel_processor.sv
  qt_raster.sv
  qt_window_fields.sv
)
list(TRANSFORM CIG_RTL_SV_NAMES PREPEND ${CMAKE_CURRENT_LIST_DIR}/ OUTPUT_VARIABLE CIG_RTL_SV)

# Every .sv of this folder listed, none at rtl/'s top (check_sources.cmake).
include(${CMAKE_CURRENT_LIST_DIR}/../check_sources.cmake)
cig_check_rtl_folder("${CIG_RTL_SV}" CIG_RTL_SV_NAMES)
