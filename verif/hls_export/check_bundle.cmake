# ctest hls_export.bundle.TOP: TOP's bundle, exported to OUT (outside the tree) by
# `tools/hls_export.sh all` (the fixture hls_export.safety.all), built with the system compiler
# from the bundle alone, in both type configurations, into BUILD, and its vectors replayed from
# inside the bundle (the testbench's default path). README_EXPECT: text the bundle's README.md
# must hold (a port's row), or empty.
if(NOT EXISTS ${OUT}/.cig-hls-bundle)
  message(FATAL_ERROR "${OUT}: no bundle (hls_export.safety.all exports every top there)")
endif()
foreach(f README.md run_vitis.tcl run_catapult.tcl src/${TOP}.cpp tb/tb_${TOP}.cpp vectors/${TOP}.vec)
  if(NOT EXISTS ${OUT}/${f})
    message(FATAL_ERROR "the bundle has no ${f}")
  endif()
endforeach()
if(NOT README_EXPECT STREQUAL "")
  file(READ ${OUT}/README.md readme)
  string(FIND "${readme}" "${README_EXPECT}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the bundle's README.md does not state: ${README_EXPECT}")
  endif()
endif()
file(REMOVE_RECURSE ${BUILD})
file(MAKE_DIRECTORY ${BUILD})
foreach(config native systemc)
  # Native: C++14, what Vitis HLS and Catapult take, with every C++17 construct an error. SystemC:
  # the standard Debian's libsystemc was built with (its headers check it when linking).
  set(flags -std=c++14 -pedantic-errors -Werror -Wall -O1 -I.)
  set(libs)
  if(config STREQUAL systemc)
    set(flags -std=c++17 -O1 -I. -DCIG_HLS_SYSTEMC)
    set(libs -lsystemc)
  endif()
  set(exe ${BUILD}/tb_${TOP}_${config})
  execute_process(COMMAND g++ ${flags} tb/tb_${TOP}.cpp src/${TOP}.cpp ${libs} -o ${exe}
    WORKING_DIRECTORY ${OUT} RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${TOP} (${config}) does not build from the bundle: ${err}")
  endif()
  execute_process(COMMAND ${exe} WORKING_DIRECTORY ${OUT} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "tb_${TOP} (${config}) exit ${rc}: ${out}${err}")
  endif()
  message(STATUS "${config}: ${out}")
endforeach()
file(REMOVE_RECURSE ${BUILD})
