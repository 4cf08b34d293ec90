# `cig cosim --trace` end to end (cmake -DCIG=<cig> -DSOURCE=<repo> -DWORK=<dir> -DFST2VCD=<fst2vcd>
# -DPYTHON=<python3> -P <this>), on small images (a 64-line polygon list at 4p2t, 895 cycles; stage
# F's N_PP = 8 array on scenes/polyhedra.json frame 0, 3851 cycles):
#   1. a window (--trace-cycles 300:399) of the quadtree's image: fst2vcd reads it, its timescale is
#      1 ns, its time axis starts at 300 x 10 ns and ends within cycle 399, every signal its save
#      file names is in it (check_trace.py), the report has the window; it is much smaller than
#      the full trace of the same image (also checked); the same window at --trace-depth 3 is
#      smaller again and its save file still names only signals present;
#   2. stage F: cycles 100:299 at its 3 ns period, the same checks;
#   3. progress on stderr when it is not a terminal: no '\r', one line per image (1, and 2 for two
#      frames of stage F);
#   4. bad requests: exit status 2, the option named, no trace, save file or report left behind:
#      --trace-cycles without --trace, B < A, not A:B, beyond the image's cycles (both processors),
#      --trace-depth without --trace, --fan-split with --processor invparam;
#   5. --fan-split off: the report says which stream was counted.
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(polys ${SOURCE}/scenes/small/overlap.polys.json)
set(poly_scene ${SOURCE}/scenes/polyhedra.json)
set(ip_args ${poly_scene} --processor invparam --pps 8 --frame 0 --channel 1)

function(expect_ok name)
  execute_process(COMMAND ${CIG} cosim ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name}: cig cosim ${ARGN} exited with ${rc}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

# fst2vcd, then check_trace.py on the VCD and the save file.
function(check_trace fst unit first last_from last_to)
  execute_process(COMMAND ${FST2VCD} ${fst} OUTPUT_FILE ${fst}.vcd RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "fst2vcd ${fst} exited with ${rc}: ${err}")
  endif()
  execute_process(COMMAND ${PYTHON} ${SOURCE}/verif/cosim/check_trace.py --vcd ${fst}.vcd --gtkw ${fst}.gtkw
                          --unit ${unit} --first ${first} --last-from ${last_from} --last-to ${last_to}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${fst}: ${out}")
  endif()
  message(STATUS "${out}")
endfunction()

# One progress line per image on stderr, no carriage return.
function(check_progress err images)
  string(FIND "${err}" "\r" cr)
  string(REGEX MATCHALL "cig cosim: [0-9]+/${images} frame [0-9]+ channel [0-9]+: [0-9]+ cycles \\([0-9.]+ s\\)\n"
         lines "${err}")
  list(LENGTH lines n)
  string(REGEX MATCHALL "\n" newlines "${err}")
  list(LENGTH newlines all)
  if(NOT cr EQUAL -1 OR NOT n EQUAL images OR NOT all EQUAL images)
    message(FATAL_ERROR "progress: expected ${images} line(s), one per image, no '\\r'; stderr was:\n${err}")
  endif()
endfunction()

# 1. The quadtree: a window, the full image, the window at depth 3.
expect_ok(window ${polys} --arch 4p2t --trace ${WORK}/win.fst --trace-cycles 300:399 --report ${WORK}/win.json)
check_progress("${err}" 1)
if(NOT out MATCHES "trace: frame 0 channel 0, cycles 300:399 \\(100 cycles of 10 ns")
  message(FATAL_ERROR "no trace summary:\n${out}")
endif()
check_trace(${WORK}/win.fst 1ns 3000 3990 3999)
file(READ ${WORK}/win.json rep)
string(JSON first GET "${rep}" trace first_cycle)
string(JSON last GET "${rep}" trace last_cycle)
if(NOT first EQUAL 300 OR NOT last EQUAL 399)
  message(FATAL_ERROR "report: trace cycles ${first}:${last}")
endif()
expect_ok(full ${polys} --arch 4p2t --trace ${WORK}/full.fst)
check_trace(${WORK}/full.fst 1ns 0 8940 8949)  # cycles 0..894
file(SIZE ${WORK}/win.fst win_size)
file(SIZE ${WORK}/full.fst full_size)
math(EXPR win_x3 "3 * ${win_size}")
if(NOT win_x3 LESS full_size)
  message(FATAL_ERROR "a 100-cycle window has ${win_size} bytes, the full 895-cycle trace ${full_size}")
endif()
expect_ok(depth ${polys} --arch 4p2t --trace ${WORK}/depth.fst --trace-cycles 300:399 --trace-depth 3)
check_trace(${WORK}/depth.fst 1ns 3000 3990 3999)
file(SIZE ${WORK}/depth.fst depth_size)
if(NOT depth_size LESS win_size)
  message(FATAL_ERROR "--trace-depth 3: ${depth_size} bytes, not below the full depth's ${win_size}")
endif()

# 2. Stage F: cycles 100..299 at 3 ns (rising edges at 300 .. 897 ns).
expect_ok(ip_window ${ip_args} --trace ${WORK}/ip.fst --trace-cycles 100:299)
check_progress("${err}" 1)
check_trace(${WORK}/ip.fst 1ns 300 897 899)

# 3. Progress over two frames of stage F.
expect_ok(ip_frames ${poly_scene} --processor invparam --pps 8 --frames 0:1 --channel 1)
check_progress("${err}" 2)

# 4. Bad requests leave nothing behind.
foreach(case IN ITEMS
    "${polys};--trace-cycles;0:10|--trace-cycles: needs --trace"
    "${polys};--trace;@/e.fst;--trace-cycles;10:5|--trace-cycles: '10:5': B < A"
    "${polys};--trace;@/e.fst;--trace-cycles;5|--trace-cycles: '5' is not of the form A:B"
    "${polys};--arch;4p2t;--trace;@/e.fst;--trace-cycles;800:900|--trace-cycles: cycles 800:900 are outside the cycles of frame 0 channel 0, 0:894"
    "${poly_scene};--processor;invparam;--pps;8;--frame;0;--channel;1;--trace;@/e.fst;--trace-cycles;0:5|--trace-cycles: cycles 0:5 are outside the cycles of frame 0 channel 1, 1:3851"
    "${polys};--trace-depth;3|--trace-depth: needs --trace"
    "${poly_scene};--processor;invparam;--fan-split;off|--fan-split: only with --processor quadtree")
  string(REPLACE "@" "${WORK}" case "${case}")
  string(REPLACE "|" ";" parts "${case}")
  list(POP_BACK parts expect)
  execute_process(COMMAND ${CIG} cosim ${parts} --report ${WORK}/e.json
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(FIND "${err}" "${expect}" at)
  if(NOT rc EQUAL 2 OR at EQUAL -1 OR EXISTS ${WORK}/e.json OR EXISTS ${WORK}/e.fst OR EXISTS ${WORK}/e.fst.gtkw)
    message(FATAL_ERROR "cig cosim ${parts}: expected status 2, '${expect}' and no file; got ${rc}\n${out}\n${err}")
  endif()
endforeach()

# 5. The stream counted, in the report.
expect_ok(fan_split_off ${polys} --fan-split off --report ${WORK}/off.json)
file(READ ${WORK}/off.json rep)
string(JSON top GET "${rep}" fan_split)
string(JSON run GET "${rep}" runs 0 stream fan_split)
if(top OR run OR NOT out MATCHES "fan split off")
  message(FATAL_ERROR "--fan-split off: the report says ${top} / ${run}\n${out}")
endif()
message(STATUS "ok")
