# cig arch --processor invparam: the seed's setting (m = 6, P = N_n = 512, t_t = 3 ns) prints the
# seed's frame-time formula for n = 1000 (N_K = 28004: 28004 * 511 + 28004 + 512 + 3 = 14338563
# clocks) and the covered-columns limit at width 50, m / (4 (m + 1) 50 t_t) = 1428571 faces/s;
# --report writes the same numbers.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${CIG} arch --processor invparam --objects 1000 --widths 50 --report ${WORK}/r.json
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cig arch --processor invparam failed (${rc}):\n${out}\n${err}")
endif()
foreach(expected "1000 +28004 +14338563 +43.016" "covered columns tend to 1428571 faces/s" "> 1.6 M faces/s")
  if(NOT out MATCHES "${expected}")
    message(FATAL_ERROR "the output lacks '${expected}':\n${out}")
  endif()
endforeach()
file(READ ${WORK}/r.json report)
string(JSON clocks GET "${report}" full 0 clocks)
if(NOT clocks EQUAL 14338563)
  message(FATAL_ERROR "report: full[0].clocks = ${clocks}, expected 14338563")
endif()
message(STATUS "ok")
