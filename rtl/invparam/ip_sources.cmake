# The inverse-parameter RTL's source files (rtl/invparam/) in compile order (the package first):
# CIG_IP_RTL_SV (absolute paths), the one list every consumer uses: verif/rtl (lint, limits, the
# Verilated PP test), verif/cosim (the Verilated array) and tools/synth_report.sh (which reads the
# names below).
set(CIG_IP_RTL_SV_NAMES
  ip_pkg.sv
  ip_cm.sv
  ip_pe.sv
  ip_sm.sv
  ip_array.sv
)
list(TRANSFORM CIG_IP_RTL_SV_NAMES PREPEND ${CMAKE_CURRENT_LIST_DIR}/ OUTPUT_VARIABLE CIG_IP_RTL_SV)
# The RTL's parameter W is the register width: the seed's word of w bits plus CIG_IP_GUARD_BITS
# (hls/invparam/word.hpp kGuardBits; hls Word<w> = WideInt<w + 16>). The configurations are named
# by the seed's w (Vip_array_w64_n8 has W = 80); the harnesses check W against hls word_bits(w).
set(CIG_IP_GUARD_BITS 16)

# A file in rtl/invparam/ missing from this list would silently drop out of lint, synthesis and
# the models; a module at rtl/'s top would belong to no processor.
file(GLOB cig_ip_rtl_sv_present CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/*.sv)
foreach(file IN LISTS cig_ip_rtl_sv_present)
  if(NOT file IN_LIST CIG_IP_RTL_SV)
    message(FATAL_ERROR "${file} is not listed in ${CMAKE_CURRENT_LIST_FILE} (CIG_IP_RTL_SV_NAMES)")
  endif()
endforeach()
get_filename_component(cig_rtl_dir ${CMAKE_CURRENT_LIST_DIR} DIRECTORY)
file(GLOB cig_ip_rtl_sv_stray CONFIGURE_DEPENDS ${cig_rtl_dir}/*.sv)
if(cig_ip_rtl_sv_stray)
  message(FATAL_ERROR "${cig_ip_rtl_sv_stray}: a module at rtl/'s top; put it in its processor's folder")
endif()
