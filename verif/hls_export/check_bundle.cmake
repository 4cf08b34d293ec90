# ctest hls_export.bundle.TOP: TOP's bundle, exported to OUT (outside the tree) by
# `tools/hls_export.sh all` (the fixture hls_export.safety.all): its Vitis configuration names TOP
# and files the bundle holds; every source compiles as C++14 with -pedantic-errors in both type
# configurations; the testbench, built with the system compiler from the bundle alone in both
# configurations into BUILD, replays its vectors from inside the bundle (the testbench's default
# path). README_EXPECT: text the bundle's README.md must hold (a port's row), or empty.
if(NOT EXISTS ${OUT}/.cig-hls-bundle)
  message(FATAL_ERROR "${OUT}: no bundle (hls_export.safety.all exports every top there)")
endif()
foreach(f README.md hls_config.cfg run_vitis.tcl run_catapult.tcl src/${TOP}.cpp tb/tb_${TOP}.cpp vectors/${TOP}.vec)
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

# hls_config.cfg (v++ -c --mode hls): the top, its synthesis source, the testbench and the vectors,
# every named file present, C++14.
file(STRINGS ${OUT}/hls_config.cfg cfg REGEX "^(syn|tb)\\.")
foreach(line "syn.top=${TOP}" "syn.file=src/${TOP}.cpp" "tb.file=tb/tb_${TOP}.cpp" "tb.file=vectors/${TOP}.vec"
        "syn.cflags=-std=c++14 -I." "tb.cflags=-std=c++14 -I.")
  list(FIND cfg "${line}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the bundle's hls_config.cfg does not state ${line}")
  endif()
endforeach()
foreach(line IN LISTS cfg)
  if(line MATCHES "^(syn|tb)\\.file=(.*)$")
    if(NOT EXISTS ${OUT}/${CMAKE_MATCH_2})
      message(FATAL_ERROR "the bundle's hls_config.cfg names ${CMAKE_MATCH_2}, which the bundle lacks")
    endif()
  elseif(line MATCHES "^syn\\.(top|directive\\.[a-z]+)=([A-Za-z_0-9]+)")
    if(NOT CMAKE_MATCH_2 STREQUAL TOP)
      message(FATAL_ERROR "the bundle's hls_config.cfg names the top ${CMAKE_MATCH_2}, not ${TOP}: ${line}")
    endif()
  endif()
endforeach()

# C++14 (the common subset of Vitis HLS and Catapult), every C++17 construct an error, in both type
# configurations: the SystemC one compiled only (its library is linked as C++17, below).
foreach(source tb/tb_${TOP}.cpp src/${TOP}.cpp)
  foreach(define CIG_HLS_NATIVE CIG_HLS_SYSTEMC)
    execute_process(COMMAND g++ -std=c++14 -pedantic-errors -Werror -Wall -D${define} -I. -fsyntax-only ${source}
      WORKING_DIRECTORY ${OUT} RESULT_VARIABLE rc ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "${source} (-D${define}) is not C++14: ${err}")
    endif()
  endforeach()
endforeach()

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
