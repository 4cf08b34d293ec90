# The inverse-parameter RTL's source files in compile order (the package first): CIG_IP_RTL_SV
# (absolute paths), the one list every consumer uses: verif/rtl (lint, limits, the Verilated PP
# test), verif/cosim (the Verilated array) and tools/synth_report.sh (which reads the names below).
set(CIG_IP_RTL_SV_NAMES
  ip_pkg.sv
  ip_pe.sv
  ip_array.sv
)
list(TRANSFORM CIG_IP_RTL_SV_NAMES PREPEND ${CMAKE_CURRENT_LIST_DIR}/ OUTPUT_VARIABLE CIG_IP_RTL_SV)
