# cig_verilate(TARGET ...): verilate() (Verilator's CMake flow, as in its examples/cmake_*) with
# the project's compile options for the generated C++, chosen for build time:
#   * model code that runs every clock (Verilator's "fast" classes): -O1. Against -O2 it compiles
#     about 3x faster (a 27 s file of the 9p model: 8 s) and simulates about as fast (bench_rtl
#     airfield 9p, alternating runs: 28-40 k cycles/s at -O1, 28-33 k at -O2);
#   * code that runs once (construction, initial values: the "slow" classes): -O0, as
#     Verilator's own makefiles leave it unoptimised;
#   * the FST trace code (runs only with `cig cosim --trace`): -O0.
# Generated code is not ours to keep warning-free (-w) and is not instrumented by the sanitizers
# (it is the simulator; the harness around it is).
# Arguments are verilate()'s (SOURCES, TOP_MODULE, PREFIX, TRACE_FST, INCLUDE_DIRS, VERILATOR_ARGS),
# and SPEED: a model built for simulation speed rather than build time (the benchmark's): the
# clocked code and the runtime at -O2.
function(cig_verilate target)
  cmake_parse_arguments(V "SPEED" "PREFIX" "" ${ARGN})
  set(args ${ARGN})
  list(REMOVE_ITEM args SPEED)
  if(V_SPEED)
    verilate(${target} ${args} OPT_FAST -O2 OPT_SLOW -O0 OPT_GLOBAL -O2)
  else()
    verilate(${target} ${args} OPT_FAST -O1 OPT_SLOW -O0 OPT_GLOBAL -O1)
  endif()
  get_target_property(sources ${target} SOURCES)
  foreach(source IN LISTS sources)
    if(source MATCHES "/${V_PREFIX}__Trace__[^/]*\\.cpp$")
      # Appended after OPT_FAST: the last -O wins.
      set_property(SOURCE ${source} APPEND_STRING PROPERTY COMPILE_FLAGS " -O0")
    endif()
  endforeach()
  target_compile_options(${target} PRIVATE -w -fno-sanitize=all)
endfunction()
