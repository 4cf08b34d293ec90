# Runs one benchmark case (FILTER) of BENCH once (--benchmark_min_time=0) and checks that it exits
# with status 0 and that its output names the case and every counter (EXPECT, a list).
execute_process(COMMAND ${BENCH} --benchmark_min_time=0 --benchmark_filter=${FILTER}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${BENCH} exited with ${rc}\n${out}\n${err}")
endif()
foreach(text IN LISTS EXPECT)
  string(FIND "${out}" "${text}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "benchmark output lacks '${text}':\n${out}")
  endif()
endforeach()
# A counter that printed as zero would mean the engine reported nothing.
if(out MATCHES "cycles/s=0/s" OR out MATCHES "segments/s=0/s" OR out MATCHES "pixels/s=0/s" OR out MATCHES "samples/s=0/s" OR out MATCHES "windows/s=0/s")
  message(FATAL_ERROR "a counter is zero:\n${out}")
endif()
message(STATUS "ok:\n${out}")
