# `cig cosim` end to end (cmake -DCIG=<cig> -DSOURCE=<repo> -DWORK=<dir> -P <this>):
#   1. a polygon list through the pipeline-tree 4p2t with an FST trace and a JSON report: exit 0,
#      the table, zero mismatches and equal cycles in the report, a non-empty waveform;
#   2. with stalls (input gaps, output back-pressure): still zero mismatches (the model replays them);
#   3. an architecture the RTL build does not have: status 2, the rule named, no report written.
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(polys ${SOURCE}/scenes/small/overlap.polys.json)

execute_process(COMMAND ${CIG} cosim ${polys} --arch 4p2t --trace ${WORK}/wave.fst --report ${WORK}/report.json
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cig cosim exited with ${rc}\n${out}\n${err}")
endif()
if(NOT out MATCHES "architecture 4p2t \\(9 PEs\\)" OR NOT out MATCHES "all: [1-9][0-9]* records compared, 0 mismatches, 0 image")
  message(FATAL_ERROR "unexpected table:\n${out}")
endif()
file(READ ${WORK}/report.json rep)
string(JSON mism GET "${rep}" mismatches)
string(JSON cm GET "${rep}" runs 0 cycles_model)
string(JSON cr GET "${rep}" runs 0 cycles_rtl)
if(NOT mism EQUAL 0 OR NOT cm EQUAL cr OR cm LESS 10)
  message(FATAL_ERROR "report: mismatches ${mism}, cycles model ${cm}, RTL ${cr}")
endif()
file(SIZE ${WORK}/wave.fst fst_size)
if(fst_size LESS 1000)
  message(FATAL_ERROR "the FST waveform has ${fst_size} bytes")
endif()

execute_process(COMMAND ${CIG} cosim ${polys} --input-gaps 30 --output-stalls 40 --stall-seed 7
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "0 mismatches, 0 image")
  message(FATAL_ERROR "cig cosim with stalls exited with ${rc}\n${out}\n${err}")
endif()

execute_process(COMMAND ${CIG} cosim ${polys} --arch 5p --report ${WORK}/bad.json
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "--arch" OR EXISTS ${WORK}/bad.json)
  message(FATAL_ERROR "--arch 5p: expected status 2 naming --arch and no report; got ${rc}\n${out}\n${err}")
endif()
message(STATUS "ok:\n${out}")
