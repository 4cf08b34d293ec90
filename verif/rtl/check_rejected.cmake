# A parameter limit of the quadtree RTL (rtl/quadtree/qt_pkg.sv, checked by $error at elaboration):
# TOOL (verilator: `--lint-only -Wall`; yosys: `read_verilog -sv` + `hierarchy -check`) on module
# TOP of SOURCES with PARAMS (NAME=VALUE;...) must fail and print EXPECT, or, with EXPECT empty,
# pass cleanly (the good defaults).
# Usage: cmake -DTOOL=verilator|yosys -DVERILATOR=<path> -DYOSYS=<path> -DTOP=<module>
#              -DPARAMS=<list> -DEXPECT=<text> -DSOURCES=<list> -P <this>
cmake_minimum_required(VERSION 3.25)
set(label "${TOP} ${PARAMS}")
if(TOOL STREQUAL "verilator")
  set(command ${VERILATOR} --lint-only -Wall --top-module ${TOP})
  foreach(p IN LISTS PARAMS)
    list(APPEND command -G${p})
  endforeach()
  list(APPEND command ${SOURCES})
elseif(TOOL STREQUAL "yosys")
  # One -p per command: a ';' inside a CMake list element would split it.
  string(REPLACE ";" " " files "${SOURCES}")
  set(hierarchy "hierarchy -check -top ${TOP}")
  foreach(p IN LISTS PARAMS)
    string(REPLACE "=" " " name_value ${p})
    string(APPEND hierarchy " -chparam ${name_value}")
  endforeach()
  set(command ${YOSYS} -q -p "read_verilog -sv ${files}" -p "${hierarchy}")
else()
  message(FATAL_ERROR "TOOL must be verilator or yosys, not '${TOOL}'")
endif()

execute_process(COMMAND ${command} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
set(log "${out}${err}")
if(EXPECT STREQUAL "")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${TOOL} rejected ${label} (exit ${rc}), expected it to pass:\n${log}")
  endif()
  message(STATUS "${TOOL} accepts ${label}")
else()
  if(rc EQUAL 0)
    message(FATAL_ERROR "${TOOL} accepted ${label}; expected it to fail with '${EXPECT}':\n${log}")
  endif()
  string(FIND "${log}" "${EXPECT}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${TOOL} rejected ${label} (exit ${rc}) but without '${EXPECT}':\n${log}")
  endif()
  message(STATUS "${TOOL} rejects ${label}: ${EXPECT}")
endif()
