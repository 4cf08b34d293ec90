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

# Every .sv of this folder listed, none at rtl/'s top (check_sources.cmake).
include(${CMAKE_CURRENT_LIST_DIR}/../check_sources.cmake)
cig_check_rtl_folder("${CIG_IP_RTL_SV}" CIG_IP_RTL_SV_NAMES)
