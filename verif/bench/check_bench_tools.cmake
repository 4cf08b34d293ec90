# ctest bench.tools: the benchmark's Python tools on fixtures (verif/bench/fixtures/), no timing:
#   * tools/bench_check.py, the regression guard: a run whose ratios are within 15 % of the committed
#     ones passes (exit 0); one with a ratio 16 % worse and an engine that now refuses a list fails
#     (exit 1) naming both, with the committed and new ratios (medians of the repetitions);
#   * tools/bench_curves.py: exponents fitted exactly on times that grow as n, n^2, n^0.5, the
#     refused and n/a points left out and named, the engine growing faster than llvmpipe named, a plot;
#   * tools/bench_results.py: a section appended, then replaced, the head kept.
#   cmake -DPYTHON=... -DSOURCE=<source dir> -DWORK=<scratch folder> [-DGNUPLOT=...] -P check_bench_tools.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(fixtures ${SOURCE}/verif/bench/fixtures)

# Runs tools/TOOL with ARGN; fails unless it exits with `status` and prints every text of `expect`.
function(expect_run tool status expect)
  execute_process(COMMAND ${PYTHON} ${SOURCE}/tools/${tool} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL status)
    message(FATAL_ERROR "${tool} ${ARGN}: exit ${rc}, expected ${status}\n${out}\n${err}")
  endif()
  foreach(text IN LISTS expect)
    string(FIND "${out}" "${text}" pos)
    if(pos EQUAL -1)
      message(FATAL_ERROR "${tool} ${ARGN}: the output lacks '${text}':\n${out}\n${err}")
    endif()
  endforeach()
  set(output "${out}" PARENT_SCOPE)
endfunction()

set(committed ${fixtures}/guard_results.md)
expect_run(bench_check.py 0 "9 ratio(s) compared with ${committed}, 0 worse by more than 15 %"
           ${committed} ${fixtures}/guard_within.json)
# depth10 quadtree: 150, 210 and 400 ms over llvmpipe's 100 (median 2.10 against 1.81); tris10k
# segment refused.
set(beyond_expect "depth10 quadtree: committed ratio 1.81, new ratio 2.10 (+16 %)"
  "tris10k segment: committed ratio 1.59, now refused" "2 worse by more than 15 %")
expect_run(bench_check.py 1 "${beyond_expect}" ${committed} ${fixtures}/guard_beyond.json)
string(FIND "${output}" "depth10 float" pos)
if(NOT pos EQUAL -1)
  message(FATAL_ERROR "bench_check.py named a ratio within 15 %:\n${output}")
endif()

# The fixture's times: llvmpipe and float grow as n, segment as n^2 (refused above 16000),
# quadtree as n^0.5 (dropping at 64000), quadtree-double as n^1.02 (within the margin of 0.05).
set(curves_expect
  "| segment | **2.00** |"
  "| segment-double | - |\n"
  "| 64000 | 1280.0 | refused | n/a | 320.0 (1234 dropped) | 2086.5 | 640.0 |"
  "* refused: segment at 64000, 256000: the segment engine takes at most 65536 polygons"
  "| segment | 2.00 | 1000..16000 (3 points) | 1.00 | **faster** |"
  "| segment-double | - | fewer than two points |"
  "| quadtree | 0.50 | 1000..256000 (5 points), polygons dropped at 64000 | 1.00 | no |"
  "| quadtree-double | 1.02 | 1000..256000 (5 points) | 1.00 | no |"
  "**polygon count: grows faster than llvmpipe: segment (2.00 against 1.00)** (margin 0.05)")
if(GNUPLOT)
  expect_run(bench_curves.py 0 "${curves_expect}" ${fixtures}/curves.json --plots ${WORK} --machine m --date d
             --commit c)
  if(NOT EXISTS ${WORK}/curves_polys.png)
    message(FATAL_ERROR "bench_curves.py drew no ${WORK}/curves_polys.png")
  endif()
  file(WRITE ${WORK}/curves.md "${output}")
else()
  file(WRITE ${WORK}/curves.md "## Cost curves\n")
  message(STATUS "gnuplot not found: bench_curves.py not run")
endif()

# A section appended to a RESULTS.md without one, then replaced: one section, the head unchanged.
file(WRITE ${WORK}/other.md "## Another curves section\n")
expect_run(bench_results.py 0 "<!-- bench: begin curves" ${committed} --section curves=${WORK}/curves.md)
file(WRITE ${WORK}/RESULTS.md "${output}")
expect_run(bench_results.py 0 "## Another curves section\n<!-- bench: end curves -->" ${WORK}/RESULTS.md
           --section curves=${WORK}/other.md)
file(READ ${committed} head)
string(FIND "${output}" "${head}" at)
string(REGEX MATCHALL "bench: begin curves" begins "${output}")
list(LENGTH begins count)
if(NOT at EQUAL 0 OR NOT count EQUAL 1)
  message(FATAL_ERROR "bench_results.py: the head must stay and the section be replaced:\n${output}")
endif()
message(STATUS "bench tools: the guard passes within 15 % and fails beyond; curves fitted; sections replaced")
