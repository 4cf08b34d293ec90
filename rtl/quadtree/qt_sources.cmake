# The quadtree RTL's source files in compile order (the package first: yosys and Verilator read
# qt_pkg before the modules that name it): the one list that every consumer uses, CIG_RTL_SV
# (absolute paths). verif/rtl (lint, Verilated unit tests), verif/cosim (Verilated
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

# A file in rtl/ missing from both lists (this one and stage F's, ip_sources.cmake) would silently
# drop out of lint, synthesis and the models.
include(${CMAKE_CURRENT_LIST_DIR}/../invparam/ip_sources.cmake)
file(GLOB cig_rtl_sv_present CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/*.sv)
foreach(file IN LISTS cig_rtl_sv_present)
  if(NOT file IN_LIST CIG_RTL_SV AND NOT file IN_LIST CIG_IP_RTL_SV)
    message(FATAL_ERROR "${file} is not listed in ${CMAKE_CURRENT_LIST_FILE} (CIG_RTL_SV_NAMES) "
                        "or ${CMAKE_CURRENT_LIST_DIR}/../invparam/ip_sources.cmake (CIG_IP_RTL_SV_NAMES)")
  endif()
endforeach()
