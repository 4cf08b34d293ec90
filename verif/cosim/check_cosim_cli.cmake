# `cig cosim` end to end (cmake -DCIG=<cig> -DSOURCE=<repo> -DWORK=<dir> -P <this>):
#   1. a polygon list through the pipeline-tree 4p2t with an FST trace and a JSON report: exit 0,
#      the table, zero mismatches and equal cycles in the report, a non-empty waveform;
#   2. with stalls (input gaps, output back-pressure): still zero mismatches (the model replays them);
#   3. an architecture the RTL build does not have: status 2, the rule named, no report written;
#   4. a frame with more lit pixels than the RTL's light covers, with --trace: status 2 and no trace
#      left behind;
#   5. an empty polygon list: zero mismatches and one cycle on both sides;
#   6. --processor invparam on scenes/polyhedra.json frame 0, channel 1 (N_PP = 8) with an FST trace
#      and a report: exit 0, zero mismatches, equal cycles; frames 0..1 with input gaps and VT
#      stalls: the same;
#   7. bad options: status 2 and the option named (an option of the other processor, a
#      configuration the build lacks, too many input gaps for the array, an unknown processor, a
#      polygon list for the array).
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
# 4. 4200 lights of 3 x 3 samples on distinct pixels of a 512-line raster: more than the 4096 covers.
set(lights "")
foreach(k RANGE 0 4199)
  math(EXPR col "${k} % 70")
  math(EXPR row "${k} / 70")
  math(EXPR x "${col} * 28 - 980")
  math(EXPR y "${row} * 28 - 980")
  string(APPEND lights "{\"centre\": [${x}e-3, ${y}e-3, 50], \"diameter\": 0.003},")
endforeach()
string(REGEX REPLACE ",$" "" lights "${lights}")
file(WRITE ${WORK}/lights.polys.json
     "{\"format\": \"cig-polys\", \"version\": 1, \"raster\": 512, \"polygons\": [], \"light_points\": [${lights}]}")
execute_process(COMMAND ${CIG} cosim ${WORK}/lights.polys.json --trace ${WORK}/lights.fst
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR EXISTS ${WORK}/lights.fst)
  message(FATAL_ERROR "too many lit pixels with --trace: expected status 2 and no trace; got ${rc}\n${out}\n${err}")
endif()

# 5. An empty frame.
file(WRITE ${WORK}/empty.polys.json "{\"format\": \"cig-polys\", \"version\": 1, \"raster\": 64, \"polygons\": []}")
execute_process(COMMAND ${CIG} cosim ${WORK}/empty.polys.json --report ${WORK}/empty.json
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(READ ${WORK}/empty.json rep)
string(JSON cm GET "${rep}" runs 0 cycles_model)
string(JSON cr GET "${rep}" runs 0 cycles_rtl)
if(NOT rc EQUAL 0 OR NOT cm EQUAL 1 OR NOT cr EQUAL 1)
  message(FATAL_ERROR "empty frame: status ${rc}, cycles model ${cm}, RTL ${cr}\n${out}\n${err}")
endif()

# 6. The inverse-parameter array.
set(poly_scene ${SOURCE}/scenes/polyhedra.json)
execute_process(COMMAND ${CIG} cosim ${poly_scene} --processor invparam --pps 8 --frame 0 --channel 1
                        --trace ${WORK}/ip.fst --report ${WORK}/ip.json
                RESULT_VARIABLE rc OUTPUT_VARIABLE ip_out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT ip_out MATCHES "processor invparam, ip_array W=64, N_PP=8"
   OR NOT ip_out MATCHES "all: [1-9][0-9]* values compared, 0 mismatches, 0 frame")
  message(FATAL_ERROR "cig cosim --processor invparam exited with ${rc}\n${ip_out}\n${err}")
endif()
file(READ ${WORK}/ip.json rep)
string(JSON mism GET "${rep}" mismatches)
string(JSON cm GET "${rep}" runs 0 cycles_model)
string(JSON cr GET "${rep}" runs 0 cycles_rtl)
if(NOT mism EQUAL 0 OR NOT cm EQUAL cr OR cm LESS 100)
  message(FATAL_ERROR "invparam report: mismatches ${mism}, cycles model ${cm}, RTL ${cr}")
endif()
file(SIZE ${WORK}/ip.fst fst_size)
if(fst_size LESS 1000)
  message(FATAL_ERROR "the invparam FST waveform has ${fst_size} bytes")
endif()
execute_process(COMMAND ${CIG} cosim ${poly_scene} --processor invparam --bits 57 --pps 16 --frames 0:1 --channel 1
                        --input-gaps 30 --vt-stalls 40 --stall-seed 3
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "0 mismatches, 0 frame")
  message(FATAL_ERROR "cig cosim --processor invparam with stalls exited with ${rc}\n${out}\n${err}")
endif()

# 7. Bad options: status 2, the option (or the rule) named, no report.
foreach(case IN ITEMS
    "--processor;invparam;--arch;5p|--arch: only with --processor quadtree"
    "--processor;invparam;--output-stalls;10|--output-stalls: only with --processor quadtree"
    "--vt-stalls;20|--vt-stalls: only with --processor invparam"
    "--processor;invparam;--pps;9|--bits/--pps: the RTL build has no ip_array configuration W=64, N_PP=9"
    "--processor;invparam;--input-gaps;80|--input-gaps: at most 75"
    "--processor;invparam;--vt-stalls;90|--vt-stalls"
    "--processor;systolic|--processor")
  string(REPLACE "|" ";" parts "${case}")
  list(POP_BACK parts expect)
  execute_process(COMMAND ${CIG} cosim ${poly_scene} ${parts} --report ${WORK}/bad_ip.json
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(FIND "${err}" "${expect}" at)
  if(NOT rc EQUAL 2 OR at EQUAL -1 OR EXISTS ${WORK}/bad_ip.json)
    message(FATAL_ERROR "cig cosim ${parts}: expected status 2 and '${expect}', no report; got ${rc}\n${out}\n${err}")
  endif()
endforeach()
execute_process(COMMAND ${CIG} cosim ${polys} --processor invparam --report ${WORK}/bad_ip.json
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "draws convex polyhedra" OR EXISTS ${WORK}/bad_ip.json)
  message(FATAL_ERROR "a polygon list with --processor invparam: expected status 2; got ${rc}\n${out}\n${err}")
endif()
message(STATUS "ok:\n${out}\n${ip_out}")
