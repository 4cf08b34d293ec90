# Runs one benchmark case (FILTER) of BENCH once (--benchmark_min_time=0) and checks that it exits
# with status 0 and that its output names the case and every counter (EXPECT, a list), and that the
# counters in MINIMA reach their floors. ARGS: the benchmark's own options (a list), if any.
execute_process(COMMAND ${BENCH} ${ARGS} --benchmark_min_time=0 --benchmark_filter=${FILTER}
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
# Optional floors (MINIMA, a list of NAME=VALUE): the counter NAME must print at least VALUE.
foreach(minimum IN LISTS MINIMA)
  string(REPLACE "=" ";" pair "${minimum}")
  list(GET pair 0 name)
  list(GET pair 1 floor)
  if(NOT out MATCHES "${name}=([0-9.]+)")
    message(FATAL_ERROR "benchmark output lacks the counter '${name}':\n${out}")
  endif()
  if(CMAKE_MATCH_1 LESS floor)
    message(FATAL_ERROR "${name}=${CMAKE_MATCH_1} is below ${floor}:\n${out}")
  endif()
endforeach()
message(STATUS "ok:\n${out}")
