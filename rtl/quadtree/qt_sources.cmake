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

# A file in rtl/quadtree/ missing from this list would silently drop out of lint, synthesis and
# the models; a module at rtl/'s top would belong to no processor (each has its folder:
# rtl/quadtree/, rtl/invparam/).
file(GLOB cig_rtl_sv_present CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/*.sv)
foreach(file IN LISTS cig_rtl_sv_present)
  if(NOT file IN_LIST CIG_RTL_SV)
    message(FATAL_ERROR "${file} is not listed in ${CMAKE_CURRENT_LIST_FILE} (CIG_RTL_SV_NAMES)")
  endif()
endforeach()
get_filename_component(cig_rtl_dir ${CMAKE_CURRENT_LIST_DIR} DIRECTORY)
file(GLOB cig_rtl_sv_stray CONFIGURE_DEPENDS ${cig_rtl_dir}/*.sv)
if(cig_rtl_sv_stray)
  message(FATAL_ERROR "${cig_rtl_sv_stray}: a module at rtl/'s top; put it in its processor's folder")
endif()
