# A top's filelist for other simulators (rtl/<processor>/TOP.f) against the CMake source list it
# mirrors:
#   cmake -DVERILATOR=<verilator> -DRTL=<repo>/rtl/<processor> -DTOP=<module> -DNAMES=<file;...> -P <this>
#   1. the list's entries (lines without their // comments, blank lines dropped) are NAMES, in
#      order: rtl/quadtree/qt_sources.cmake's or rtl/invparam/ip_sources.cmake's, so the two cannot
#      drift apart;
#   2. `verilator --lint-only -Wall -f TOP.f --top-module TOP` from RTL (the list's paths are
#      relative to it) and `-F RTL/TOP.f` from elsewhere (Verilator's relative-to-the-list form)
#      pass with no message.
cmake_minimum_required(VERSION 3.25)
set(list_file ${RTL}/${TOP}.f)
if(NOT EXISTS ${list_file})
  message(FATAL_ERROR "${list_file} is missing")
endif()
file(STRINGS ${list_file} lines)
set(entries "")
foreach(line IN LISTS lines)
  string(REGEX REPLACE "//.*$" "" line "${line}")
  string(STRIP "${line}" line)
  if(NOT line STREQUAL "")
    list(APPEND entries "${line}")
  endif()
endforeach()
if(NOT entries STREQUAL NAMES)
  message(FATAL_ERROR "${list_file} names\n  ${entries}\nbut the CMake list names\n  ${NAMES}\n"
                      "(same files, same order: edit the filelist with the CMake list)")
endif()
execute_process(COMMAND ${VERILATOR} --lint-only -Wall -f ${TOP}.f --top-module ${TOP}
                WORKING_DIRECTORY ${RTL} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT "${out}${err}" STREQUAL "")
  message(FATAL_ERROR "verilator --lint-only -Wall -f ${TOP}.f (in ${RTL}) exited with ${rc}\n${out}\n${err}")
endif()
execute_process(COMMAND ${VERILATOR} --lint-only -Wall -F ${list_file} --top-module ${TOP}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT "${out}${err}" STREQUAL "")
  message(FATAL_ERROR "verilator --lint-only -Wall -F ${list_file} exited with ${rc}\n${out}\n${err}")
endif()
list(LENGTH entries n)
message(STATUS "${TOP}.f: ${n} files, in the CMake list's order; lint clean with -f and -F")
